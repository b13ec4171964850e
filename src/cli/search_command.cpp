#include "cli/search_command.h"

#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "app/search_run.h"
#include "cli/options.h"
#include "cli/progress.h"

namespace fs = std::filesystem;

namespace curdle::cli {

void add_search_options(CLI::App& c, SearchOptions& o) {
  c.add_option("recipe", o.recipe_path, "Recipe file (TOML)")->required()->check(kNotEmpty);
  c.add_option("--seeds", o.seeds, "Seeds to try: A..B (inclusive), e.g. 1..10000")
      ->required()
      ->check(kNotEmpty);
  c.add_option("--window", o.window,
               "Segment size in cells, W,H (1-D: W): every segment of that size in each seed's "
               "field is scored (default: the whole field, or the recipe's fixed floor)")
      ->check(kNotEmpty);
  c.add_option("--stride", o.stride,
               "Cells between the corners of the segments tried (default: an eighth of the "
               "segment's smaller side)");
  c.add_option("--target", o.targets,
               std::string("A target, repeatable: ") + kTargetSyntax +
                   " (default: every value at its expected share, every curd at its expected "
                   "dimension)")
      ->allow_extra_args(false);
  c.add_option("--top", o.top, "How many seeds to keep (default 10)");
  c.add_option("--lacunarity-box", o.lacunarity_box,
               "Side in cells of the gliding box for lacunarity (default: the base b)");
  c.add_option("--out", o.out_dir,
               "Where search.csv and the previews go (default: curdle-out/<recipe name>-search)")
      ->check(kNotEmpty);
  c.add_flag("!--no-previews", o.previews, "Write search.csv only, no preview images");
  c.add_option("--set", o.sets, "Override a recipe key, as for generate")->allow_extra_args(false);
  c.add_option("--threads", o.threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  c.add_option("--max-memory", o.max_memory, "Refuse work above this much memory, e.g. 8G")
      ->check(kNotEmpty);
}

int run_search(const SearchOptions& o) {
  CommonOptions common;
  common.recipe_path = o.recipe_path;
  common.sets = o.sets;
  common.max_memory = o.max_memory;
  app::SearchRequest request;
  request.run = run_request(common);
  request.seeds = o.seeds;
  request.segment = o.window;
  request.targets = o.targets;
  request.stride = o.stride;
  request.top = o.top;
  request.lacunarity_box = o.lacunarity_box;
  request.threads = o.threads;
  const app::SearchRun search = app::resolve_search(request);
  const Design& d = search.run.recipe.design;

  std::optional<tbb::global_control> limit;
  if (o.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, o.threads);
  const fs::path dir = o.out_dir.empty() ? fs::path("curdle-out") /
                                               (fs::path(o.recipe_path).stem().string() + "-search")
                                         : fs::path(o.out_dir);
  app::StagingDirectory sink(dir, app::is_search_output_name);
  std::vector<SearchHit> hits;
  {
    Progress progress("searching");
    hits = app::run_search(search, [&](double f) { progress.update(f); });
  }
  const nlohmann::ordered_json j = app::search_hits_json(search, hits);
  const auto previews = app::write_search_outputs(search, hits, j, o.previews, sink);
  sink.commit();

  const SearchSpec& spec = search.spec;
  std::printf("%s: seeds %llu to %llu, %s\n", d.name.c_str(),
              static_cast<unsigned long long>(search.first),
              static_cast<unsigned long long>(search.last),
              spec.window ? ("segments of " + std::to_string((*spec.window)[0]) + " x " +
                             std::to_string((*spec.window)[1]) + " cells")
                                .c_str()
                          : "the whole field");
  std::printf("targets:");
  for (const auto& t : j["targets"]) std::printf(" %s", t.get<std::string>().c_str());
  // The margin ranks hits of equal score: how far inside its bounds the tightest <=, >= or
  // range target is.
  std::printf("\n%4s %20s %16s %10s %10s  %s\n", "rank", "seed", "window", "score", "margin",
              "measured");
  for (const auto& h : j["hits"]) {
    std::string measured;
    for (const auto& [name, x] : h["measured"].items()) {
      char v[32];
      std::snprintf(v, sizeof v, "%.4g", x.is_null() ? NAN : x.get<double>());
      measured +=
          (measured.empty() ? "" : "  ") + name.substr(0, name.find_first_of("<>=")) + " " + v;
    }
    char margin[32] = "-";
    if (!h["margin"].is_null())
      std::snprintf(margin, sizeof margin, "%.4f", h["margin"].get<double>());
    std::printf("%4d %20s %16s %10.4f %10s  %s%s\n", h["rank"].get<int>(),
                h["seed"].get<std::string>().c_str(), h["window"].get<std::string>().c_str(),
                h["score"].get<double>(), margin, measured.c_str(),
                h["meets_empty_zones"].get<bool>() ? "" : "  (an empty zone is occupied)");
  }
  if (!hits.empty()) std::printf("best: %s\n", j["hits"][0]["command"].get<std::string>().c_str());
  std::printf("outputs in %s: search.csv%s\n", fs::absolute(dir).lexically_normal().c_str(),
              o.previews ? (", " + std::to_string(previews.size()) + " previews").c_str() : "");
  return 0;
}

}  // namespace curdle::cli
