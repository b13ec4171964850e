#include "cli/search_command.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>

#include "cli/progress.h"
#include "curdle/curdling.h"
#include "curdle/error.h"
#include "export/atomic_file.h"
#include "export/csv_field.h"
#include "export/preview_png.h"

namespace fs = std::filesystem;

namespace curdle::cli {

void add_search_options(CLI::App& c, SearchOptions& o) {
  c.add_option("recipe", o.recipe_path, "Recipe file (TOML)")->required();
  c.add_option("--seeds", o.seeds, "Seeds to try: A..B (inclusive), e.g. 1..10000")->required();
  c.add_option("--window", o.window,
               "Segment size in cells, W,H (1-D: W): every segment of that size in each seed's "
               "field is scored (default: the whole field, or the recipe's fixed floor)");
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
               "Where search.csv and the previews go (default: curdle-out/<recipe name>-search)");
  c.add_flag("!--no-previews", o.previews, "Write search.csv only, no preview images");
  c.add_option("--set", o.sets, "Override a recipe key, as for generate")
      ->allow_extra_args(false);
  c.add_option("--threads", o.threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  c.add_option("--max-memory", o.max_memory, "Refuse work above this much memory, e.g. 8G");
}

std::pair<uint64_t, uint64_t> parse_seed_range(const std::string& text, const std::string& option) {
  const size_t dots = text.find("..");
  const std::string a = text.substr(0, dots), b = dots == std::string::npos ? a : text.substr(dots + 2);
  auto number = [&](const std::string& s, uint64_t& v) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && ec == std::errc() && p == s.data() + s.size();
  };
  uint64_t first = 0, last = 0;
  if (!number(a, first) || !number(b, last) || last < first)
    throw InputError(SourceLocation{option, 0, 0, ""},
                     "'" + text + "' is not a range of seeds; write A..B with whole numbers "
                     "A <= B, e.g. 1..10000");
  return {first, last};
}

std::array<int64_t, 2> parse_segment_size(const std::string& text, int dimension,
                                          const std::string& option) {
  std::array<int64_t, 2> size{1, 1};
  const size_t comma = text.find(',');
  const std::string w = text.substr(0, comma), h = comma == std::string::npos ? "" : text.substr(comma + 1);
  auto number = [](const std::string& s, int64_t& v) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && ec == std::errc() && p == s.data() + s.size() && v >= 1;
  };
  const bool ok = dimension == 1 ? number(w, size[0]) && comma == std::string::npos
                                 : number(w, size[0]) && number(h, size[1]);
  if (!ok)
    throw InputError(SourceLocation{option, 0, 0, ""},
                     "'" + text + "' is not a segment size; write " +
                         (dimension == 1 ? "W" : "W,H") + " in whole cells, each at least 1");
  return size;
}

SearchSpec make_search_spec(const Session& s, const std::vector<std::string>& targets,
                            const std::string& window, int64_t stride, int top,
                            int64_t lacunarity_box) {
  SearchSpec spec;
  const Design& d = s.recipe.design;
  for (const std::string& t : targets) spec.targets.push_back(parse_target(t, d));
  if (!window.empty())
    spec.window = parse_segment_size(window, d.lattice.dimension, "--window");
  else if (s.recipe.window)
    spec.window = std::array<int64_t, 2>{s.recipe.window->size[0],
                                         d.lattice.dimension >= 2 ? s.recipe.window->size[1] : 1};
  spec.stride = stride;
  spec.top = top;
  spec.lacunarity_box = lacunarity_box;
  check_search(d, d.field, spec);
  return spec;
}

nlohmann::ordered_json search_hits_json(const Session& s, const std::vector<std::string>& sets,
                                        const SearchSpec& spec_in,
                                        const std::vector<SearchHit>& hits) {
  const Design& d = s.recipe.design;
  const std::vector<Target> targets =
      spec_in.targets.empty() ? default_targets(d) : spec_in.targets;
  nlohmann::ordered_json j;
  j["targets"] = nlohmann::json::array();
  for (const Target& t : targets) j["targets"].push_back(t.text);
  j["hits"] = nlohmann::json::array();
  int rank = 0;
  for (const SearchHit& h : hits) {
    nlohmann::ordered_json hit;
    hit["rank"] = ++rank;
    hit["seed"] = h.seed;
    hit["window"] = window_text(h.segment, d.lattice.dimension);
    hit["score"] = h.score;
    hit["meets_empty_zones"] = h.meets_empty_zones;
    nlohmann::ordered_json measured = nlohmann::json::object();
    for (size_t i = 0; i < targets.size(); ++i)
      measured[targets[i].text] =
          std::isnan(h.measured[i]) ? nlohmann::ordered_json(nullptr)
                                    : nlohmann::ordered_json(h.measured[i]);
    hit["measured"] = measured;
    const bool whole = h.segment == d.field;
    hit["command"] = generate_command(s.recipe_path, sets, h.seed,
                                      whole ? std::nullopt : std::optional<Box>(h.segment),
                                      d.lattice.dimension);
    j["hits"].push_back(hit);
  }
  return j;
}

int run_search(const SearchOptions& o) {
  CommonOptions common;
  common.recipe_path = o.recipe_path;
  common.sets = o.sets;
  common.max_memory = o.max_memory;
  Session s = open_session(common);
  const Design& d = s.recipe.design;
  const auto [first, last] = parse_seed_range(o.seeds, "--seeds");
  const SearchSpec spec = make_search_spec(s, o.targets, o.window, o.stride, o.top, o.lacunarity_box);
  if (last - first >= (uint64_t{1} << 40))
    throw InputError(SourceLocation{"--seeds", 0, 0, ""}, "at most 2^40 seeds a search");

  // Each thread holds one seed's curds and, for segments, the grid of values with its sums.
  std::optional<tbb::global_control> limit;
  if (o.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, o.threads);
  const uint64_t threads = o.threads > 0 ? static_cast<uint64_t>(o.threads)
                                         : static_cast<uint64_t>(tbb::info::default_concurrency());
  // The grid is 2 bytes a cell; each target reads one prefix-sum table of 4 bytes a cell.
  const uint64_t tables =
      (spec.targets.empty() ? default_targets(d).size() : spec.targets.size()) + 1;
  const uint64_t per_thread =
      estimate_memory(d, generation_box(d, d.field)) + d.field.cells() * (2 + 4 * tables);
  if (per_thread * threads > s.generate.max_memory_bytes)
    throw InputError(SourceLocation{o.recipe_path, 0, 0, ""},
                     "a search over this field needs about " +
                         std::to_string((per_thread * threads) >> 20) +
                         " MiB, above the memory limit of " +
                         std::to_string(s.generate.max_memory_bytes >> 20) +
                         " MiB; use a smaller field.cells or raise --max-memory");

  const fs::path dir = o.out_dir.empty()
                           ? fs::path("curdle-out") / (fs::path(o.recipe_path).stem().string() + "-search")
                           : fs::path(o.out_dir);
  make_output_dir(dir);
  std::vector<SearchHit> hits;
  {
    Progress progress("searching");
    hits = search_seeds(d, d.field, spec, first, last, [&](double f) { progress.update(f); });
  }
  const nlohmann::ordered_json j = search_hits_json(s, o.sets, spec, hits);

  std::vector<std::unique_ptr<StagedFile>> staged;
  staged.push_back(std::make_unique<StagedFile>(dir / "search.csv"));
  staged.back()->write([&](std::ostream& out) {
    out << "rank,seed,window,score,meets_empty_zones";
    for (const auto& t : j["targets"]) out << ',' << csv_field(t.get<std::string>());
    out << ",command\r\n";
    for (const auto& h : j["hits"]) {
      out << h["rank"].get<int>() << ',' << h["seed"].get<uint64_t>() << ','
          << csv_field(h["window"].get<std::string>()) << ',' << h["score"].get<double>() << ','
          << (h["meets_empty_zones"].get<bool>() ? 1 : 0);
      for (const auto& [name, x] : h["measured"].items())
        out << ',' << (x.is_null() ? std::string() : std::to_string(x.get<double>()));
      out << ',' << csv_field(h["command"].get<std::string>()) << "\r\n";
    }
  });
  std::vector<std::string> preview_names;
  if (o.previews)
    for (size_t i = 0; i < hits.size(); ++i) {
      char name[64];
      std::snprintf(name, sizeof name, "rank-%02zu-seed-%llu.png", i + 1,
                    static_cast<unsigned long long>(hits[i].seed));
      preview_names.push_back(name);
      const CurdField field = curdle(d, hits[i].seed, hits[i].segment);
      staged.push_back(std::make_unique<StagedFile>(dir / name));
      write_png(staged.back()->temporary(), render_preview(d, field, hits[i].segment));
    }
  for (auto& f : staged) f->check_replaceable();
  for (auto& f : staged) f->commit();

  std::printf("%s: seeds %llu to %llu, %s\n", d.name.c_str(),
              static_cast<unsigned long long>(first), static_cast<unsigned long long>(last),
              spec.window ? ("segments of " + std::to_string((*spec.window)[0]) + " x " +
                             std::to_string((*spec.window)[1]) + " cells")
                                .c_str()
                          : "the whole field");
  std::printf("targets:");
  for (const auto& t : j["targets"]) std::printf(" %s", t.get<std::string>().c_str());
  std::printf("\n%4s %20s %16s %10s  %s\n", "rank", "seed", "window", "score", "measured");
  for (const auto& h : j["hits"]) {
    std::string measured;
    for (const auto& [name, x] : h["measured"].items()) {
      char v[32];
      std::snprintf(v, sizeof v, "%.4g", x.is_null() ? NAN : x.get<double>());
      measured += (measured.empty() ? "" : "  ") + name.substr(0, name.find_first_of("<>=")) + " " + v;
    }
    std::printf("%4d %20llu %16s %10.4f  %s%s\n", h["rank"].get<int>(),
                static_cast<unsigned long long>(h["seed"].get<uint64_t>()),
                h["window"].get<std::string>().c_str(), h["score"].get<double>(), measured.c_str(),
                h["meets_empty_zones"].get<bool>() ? "" : "  (an empty zone is occupied)");
  }
  if (!hits.empty())
    std::printf("best: %s\n", j["hits"][0]["command"].get<std::string>().c_str());
  std::printf("outputs in %s: search.csv%s\n", fs::absolute(dir).lexically_normal().c_str(),
              o.previews ? (", " + std::to_string(preview_names.size()) + " previews").c_str() : "");
  return 0;
}

}  // namespace curdle::cli
