#include "app/search_run.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

#include "app/reproduce.h"
#include "app/zone_in_cells.h"
#include "curdle/curdling.h"
#include "curdle/error.h"
#include "export/report/preview_png.h"
#include "io/csv_field.h"
#include "layout/builder.h"

namespace curdle::app {

std::pair<uint64_t, uint64_t> parse_seed_range(const std::string& text, const std::string& name) {
  const size_t dots = text.find("..");
  const std::string a = text.substr(0, dots),
                    b = dots == std::string::npos ? a : text.substr(dots + 2);
  auto number = [&](const std::string& s, uint64_t& v) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && ec == std::errc() && p == s.data() + s.size();
  };
  uint64_t first = 0, last = 0;
  if (!number(a, first) || !number(b, last) || last < first)
    throw InputError(parameter(name), "'" + text +
                                          "' is not a range of seeds; write A..B with whole "
                                          "numbers A <= B, e.g. 1..10000");
  return {first, last};
}

std::array<int64_t, 2> parse_segment_size(const std::string& text, int dimension,
                                          const std::string& name) {
  std::array<int64_t, 2> size{1, 1};
  const size_t comma = text.find(',');
  const std::string w = text.substr(0, comma),
                    h = comma == std::string::npos ? "" : text.substr(comma + 1);
  auto number = [](const std::string& s, int64_t& v) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && ec == std::errc() && p == s.data() + s.size() && v >= 1;
  };
  const bool ok = dimension == 1 ? number(w, size[0]) && comma == std::string::npos
                                 : number(w, size[0]) && number(h, size[1]);
  if (!ok)
    throw InputError(parameter(name), "'" + text + "' is not a segment size; write " +
                                          (dimension == 1 ? "W" : "W,H") +
                                          " in whole cells, each at least 1");
  return size;
}

namespace {

// The open shares of a perforated layout's fabrication sheets, for sheet_open_area targets:
// the segment laid out as `curdle generate` lays it. None (the target is refused, naming why)
// when the recipe lays no perforated sheet.
std::function<std::vector<double>(const CurdField&, const Box&)> sheet_open_areas_of(
    const Run& run) {
  if (!run.recipe.layout || run.recipe.layout->kind->ground() != Ground::sheet) return {};
  return [design = run.recipe.design, spec = *run.recipe.layout](const CurdField& field,
                                                                 const Box& segment) {
    const Layout layout = make_layout(design, field, segment, spec);
    std::vector<double> shares;
    for (const FabricationSheet& sheet : layout.sheets()) shares.push_back(sheet.open_area);
    return shares;
  };
}

}  // namespace

uint64_t search_work(const Design& d, uint64_t first, uint64_t last) {
  const unsigned __int128 per_seed =
      static_cast<unsigned __int128>(d.field.cells()) * static_cast<unsigned>(d.lattice.stages) +
      kSeedWork;
  const unsigned __int128 work = (static_cast<unsigned __int128>(last - first) + 1) * per_seed;
  return work > UINT64_MAX ? UINT64_MAX : static_cast<uint64_t>(work);
}

SearchRun resolve_search(const SearchRequest& request) {
  SearchRun s;
  s.run = resolve_run(request.run);
  const Design& d = s.run.recipe.design;
  std::tie(s.first, s.last) = parse_seed_range(request.seeds, "seeds");
  if (s.last - s.first >= (uint64_t{1} << 40))
    throw ResourceLimitError(parameter("seeds"), "at most 2^40 seeds a search");
  const uint64_t work = search_work(d, s.first, s.last);
  if (request.max_work && work > request.max_work)
    throw ResourceLimitError(
        parameter("seeds"),
        std::to_string(s.first) + ".." + std::to_string(s.last) + " is " + std::to_string(work) +
            " cell-stages of work (seeds x (" + std::to_string(d.field.cells()) + " cells x " +
            std::to_string(d.lattice.stages) + " stages + " + std::to_string(kSeedWork) +
            " for each seed's own drawing, scoring and ranking)), above the budget of " +
            std::to_string(request.max_work) + "; search fewer seeds or a smaller field");
  // Each thread holds one seed's curds and, for segments, the grid of values with its sums:
  // the grid is 2 bytes a cell, and each target reads one prefix-sum table of 4 bytes a cell.
  const uint64_t threads = request.threads > 0
                               ? static_cast<uint64_t>(request.threads)
                               : static_cast<uint64_t>(tbb::info::default_concurrency());
  const uint64_t tables =
      (request.targets.empty() ? default_targets(d).size() : request.targets.size()) + 1;
  const uint64_t per_thread =
      estimate_memory(d, generation_box(d, d.field)) + d.field.cells() * (2 + 4 * tables);
  if (per_thread * threads > s.run.generate.max_memory_bytes)
    throw ResourceLimitError(
        "a search over this field needs about " + std::to_string((per_thread * threads) >> 20) +
        " MiB, above the memory limit of " + std::to_string(s.run.generate.max_memory_bytes >> 20) +
        " MiB; use a smaller field.cells" +
        (s.run.generate.memory_limit_hint.empty() ? ""
                                                  : ", or " + s.run.generate.memory_limit_hint));
  // After the memory check: a zone in mm lays the floor out once.
  for (const std::string& t : request.targets) {
    Target target = parse_target(zone_in_cells(t, s.run), d);
    target.text = t;  // reports show it as written, in mm or cells
    s.spec.targets.push_back(target);
  }
  if (std::any_of(s.spec.targets.begin(), s.spec.targets.end(),
                  [](const Target& t) { return t.measure == Measure::sheet_open_area; }))
    s.spec.sheet_open_areas = sheet_open_areas_of(s.run);
  if (!request.segment.empty())
    s.spec.window = parse_segment_size(request.segment, d.lattice.dimension, "segment");
  else if (s.run.recipe.window)
    s.spec.window = std::array<int64_t, 2>{
        s.run.recipe.window->size[0], d.lattice.dimension >= 2 ? s.run.recipe.window->size[1] : 1};
  s.spec.stride = request.stride;
  s.spec.top = request.top;
  s.spec.lacunarity_box = request.lacunarity_box;
  check_search(d, d.field, s.spec);
  return s;
}

std::vector<SearchHit> run_search(const SearchRun& s, const std::function<void(double)>& progress,
                                  const std::atomic<bool>* cancel) {
  const Design& d = s.run.recipe.design;
  return search_seeds(d, d.field, s.spec, s.first, s.last, progress, cancel);
}

nlohmann::ordered_json search_hits_json(const SearchRun& s, const std::vector<SearchHit>& hits) {
  const Design& d = s.run.recipe.design;
  const std::vector<Target> targets = s.spec.targets.empty() ? default_targets(d) : s.spec.targets;
  nlohmann::ordered_json j;
  j["targets"] = nlohmann::json::array();
  for (const Target& t : targets) j["targets"].push_back(t.text);
  j["hits"] = nlohmann::json::array();
  int rank = 0;
  for (const SearchHit& h : hits) {
    nlohmann::ordered_json hit;
    hit["rank"] = ++rank;
    hit["seed"] = std::to_string(h.seed);
    hit["window"] = window_text(h.segment, d.lattice.dimension);
    hit["score"] = h.score;
    // How far inside its bounds the tightest <=, >= or range target is: what ranks passes.
    hit["margin"] = std::isfinite(h.margin) ? nlohmann::ordered_json(h.margin)
                                            : nlohmann::ordered_json(nullptr);
    hit["meets_empty_zones"] = h.meets_empty_zones;
    nlohmann::ordered_json measured = nlohmann::json::object();
    for (size_t i = 0; i < targets.size(); ++i)
      measured[targets[i].text] = std::isnan(h.measured[i]) ? nlohmann::ordered_json(nullptr)
                                                            : nlohmann::ordered_json(h.measured[i]);
    hit["measured"] = measured;
    const bool whole = h.segment == d.field;
    hit["command"] =
        generate_command(s.run.recipe_path, s.run.overrides, h.seed,
                         whole ? std::nullopt : std::optional<Box>(h.segment), d.lattice.dimension);
    j["hits"].push_back(hit);
  }
  return j;
}

bool is_search_output_name(const std::string& name, bool folder) {
  if (folder) return false;
  return name == "search.csv" ||
         (name.rfind("rank-", 0) == 0 && name.size() > 4 && name.substr(name.size() - 4) == ".png");
}

std::vector<std::string> write_search_outputs(const SearchRun& s,
                                              const std::vector<SearchHit>& hits,
                                              const nlohmann::ordered_json& j, bool previews,
                                              OutputSink& sink) {
  sink.write("search.csv", [&](std::ostream& out) {
    out << "rank,seed,window,score,margin,meets_empty_zones";
    for (const auto& t : j["targets"]) out << ',' << csv_field(t.get<std::string>());
    out << ",command\r\n";
    for (const auto& h : j["hits"]) {
      out << h["rank"].get<int>() << ',' << h["seed"].get<std::string>() << ','
          << csv_field(h["window"].get<std::string>()) << ',' << h["score"].get<double>() << ','
          << (h["margin"].is_null() ? std::string() : std::to_string(h["margin"].get<double>()))
          << ',' << (h["meets_empty_zones"].get<bool>() ? 1 : 0);
      for (const auto& [name, x] : h["measured"].items())
        out << ',' << (x.is_null() ? std::string() : std::to_string(x.get<double>()));
      out << ',' << csv_field(h["command"].get<std::string>()) << "\r\n";
    }
  });
  std::vector<std::string> names;
  if (!previews) return names;
  const Design& d = s.run.recipe.design;
  for (size_t i = 0; i < hits.size(); ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "rank-%02zu-seed-%llu.png", i + 1,
                  static_cast<unsigned long long>(hits[i].seed));
    names.push_back(name);
    const CurdField field = curdle(d, hits[i].seed, hits[i].segment);
    const std::string png = encode_png(render_preview(d, field, hits[i].segment));
    sink.write(name, [&](std::ostream& o) { o << png; });
  }
  return names;
}

}  // namespace curdle::app
