#include "server/api.h"

#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "app/outputs.h"
#include "app/picture_study.h"
#include "app/reproduce.h"
#include "app/run.h"
#include "app/search_run.h"
#include "curdle/curdling.h"
#include "curdle/error.h"
#include "curdle/overlay.h"
#include "curdle/palette.h"
#include "curdle/report.h"
#include "export/measure_files.h"
#include "export/report_json.h"
#include "layout/builder.h"
#include "layout/cell_placement.h"

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace curdle::server {
namespace {

// The files the page may download: the registry's single-file outputs (those of a layout only
// when there is one), and the recipe.
std::vector<std::string> downloads(bool with_layout) {
  std::vector<std::string> names;
  for (const app::Output& o : app::output_registry())
    if (o.download && (with_layout || !o.needs_layout)) names.push_back(o.name);
  names.push_back("recipe.toml");
  return names;
}

// The API spells a run parameter as its query key; an override is named by its recipe key.
std::string query_key(const std::string& parameter) {
  return parameter == "set" ? std::string() : parameter + "=";
}

std::string base64(const uint8_t* data, size_t size) {
  static const char* kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (size_t i = 0; i < size; i += 3) {
    const uint32_t n = uint32_t{data[i]} << 16 | (i + 1 < size ? uint32_t{data[i + 1]} << 8 : 0) |
                       (i + 2 < size ? data[i + 2] : 0);
    out += kAlphabet[n >> 18 & 63];
    out += kAlphabet[n >> 12 & 63];
    out += i + 1 < size ? kAlphabet[n >> 6 & 63] : '=';
    out += i + 2 < size ? kAlphabet[n & 63] : '=';
  }
  return out;
}

// The parameters of a run: recipe keys become overrides, as --set does.
struct RunRequest {
  std::vector<std::string> sets;
  std::string seed, window;
  std::map<std::string, std::vector<std::string>> own;  // the endpoint's own parameters
};

RunRequest read_run(const Params& params, const std::set<std::string>& own_names) {
  if (params.size() > 256)
    throw ResourceLimitError("too many parameters (" + std::to_string(params.size()) +
                             "); at most 256");
  RunRequest r;
  for (const auto& [key, value] : params) {
    if (key == "set") {
      if (value.find('=') == std::string::npos)
        throw InputError(parameter("set"),
                         "'" + value + "' is not KEY=VALUE, e.g. set=lattice.base=3");
      r.sets.push_back(value);
    } else if (key.find('.') != std::string::npos) {
      r.sets.push_back(key + "=" + value);
    } else if (key == "seed" || key == "window") {
      // Given empty, it would read as not given: a different run from the one asked for.
      if (value.empty())
        throw InputError(parameter(key), "is empty; give a value or leave the parameter out");
      (key == "seed" ? r.seed : r.window) = value;
    } else if (own_names.count(key)) {
      r.own[key].push_back(value);
    } else {
      std::string allowed = "seed, window, set";
      for (const auto& n : own_names) allowed += ", " + n;
      throw InputError(parameter(key), "unknown parameter; allowed: " + allowed +
                                           ", and recipe keys such as lattice.base=3 or "
                                           "curds.0.probabilities=[\"1/2\",\"1/2\"]");
    }
  }
  return r;
}

// The whole text as a whole number (a leading minus allowed); nullopt for anything else (a
// plus sign, spaces, digits beyond 64 bits).
std::optional<int64_t> whole_number(const std::string& text) {
  int64_t v = 0;
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || p != text.data() + text.size()) return std::nullopt;
  return v;
}

std::string own(const RunRequest& r, const std::string& name, const std::string& fallback = "") {
  const auto it = r.own.find(name);
  return it == r.own.end() ? fallback : it->second.back();
}

// A quarter of physical memory (the default limit is half of it) for one request.
uint64_t memory_limit(const ApiContext& c) {
  return c.limits.max_memory ? c.limits.max_memory : app::default_memory_limit() / 2;
}

app::RunRequest run_request(const ApiContext& c, const RunRequest& r) {
  app::RunRequest request;
  request.recipe_path = c.recipe_path;
  request.recipe_text = c.recipe_text;
  request.seed = r.seed;
  request.overrides = r.sets;
  request.window = r.window;
  request.max_memory = memory_limit(c);
  request.memory_limit_hint = "start the server with a larger --max-memory";
  return request;
}

app::Run run_for(const ApiContext& c, const RunRequest& r) {
  return app::resolve_run(run_request(c, r));
}

void check_cells(const Design& d, const Box& view, uint64_t limit, const char* what) {
  const uint64_t cells = generation_box(d, view).cells();
  if (cells > limit)
    throw ResourceLimitError(std::string(what) + " " + std::to_string(cells) +
                             " cells; the server allows " + std::to_string(limit) +
                             ": choose a smaller field.cells or window, or start it with a larger "
                             "--max-cells");
}

ordered_json box_json(const Box& b, int dimension) {
  ordered_json j = ordered_json::array();
  for (int d = 0; d < dimension; ++d) j.push_back(b.origin[d]);
  for (int d = 0; d < dimension; ++d) j.push_back(b.size[d]);
  return j;
}

ordered_json polygon_json(const Polygon& polygon) {
  ordered_json points = ordered_json::array();
  for (const auto& p : polygon) points.push_back({p[0], p[1]});
  return points;
}

// The surface the page draws over the floor's segment: its outline and zones in mm, and where
// the segment's cells lie (mm = origin_mm + cell_mm * u, u in cells from the segment's corner,
// without a bond's course shifts).
ordered_json surface_json(const LayoutSpec& spec) {
  const auto need = elements_to_cover(spec);
  Box segment;
  segment.size = {need[0], need[1], 1};
  const CellPlacement placement = cell_placement(spec, segment);
  const auto extent = surface_extent(spec, segment);
  ordered_json zones = ordered_json::array();
  for (const Zone& z : spec.zones) {
    ordered_json zone = {{"name", z.name},
                         {"rule", z.rule == ZoneRule::exclude ? "exclude" : "value"},
                         {"polygon", polygon_json(z.polygon)}};
    if (z.rule == ZoneRule::value) zone["value"] = z.value;
    zones.push_back(zone);
  }
  return {
      {"origin_mm", {placement.origin[0], placement.origin[1]}},
      {"cell_mm", {placement.scale[0], placement.scale[1]}},
      {"outline_mm",
       polygon_json(spec.outline.empty()
                        ? Polygon{{0, 0}, {extent[0], 0}, {extent[0], extent[1]}, {0, extent[1]}}
                        : spec.outline)},
      {"zones", zones}};
}

// What the page draws and edits: the design, layout facts and the legend.
ordered_json describe(const app::Run& s) {
  const Design& d = s.recipe.design;
  const int E = d.lattice.dimension;
  ordered_json j;
  j["name"] = d.name;
  j["description"] = s.recipe.design.description;
  j["recipe_path"] = s.recipe_path;
  j["lattice"] = {{"base", d.lattice.base},
                  {"dimension", E},
                  {"stages", d.lattice.stages},
                  {"mode", std::string(to_string(d.lattice.mode))}};
  j["curds"] = ordered_json::array();
  for (size_t c = 0; c < d.curds.size(); ++c) {
    ordered_json p = ordered_json::array();
    for (const Probability& q : d.curds[c].probabilities) p.push_back(q.text());
    j["curds"].push_back(
        {{"name", d.curds[c].name}, {"probabilities", p}, {"colour", hex_colour(curd_colour(d.curds, c))}});
  }
  ordered_json field = ordered_json::array();
  for (int k = 0; k < E; ++k) field.push_back(d.field.size[k]);
  j["field"] = field;
  j["default_window"] = s.recipe.window ? box_json(*s.recipe.window, E) : ordered_json(nullptr);
  ordered_json legend = ordered_json::array();
  if (s.recipe.layout) {
    const LayoutSpec& spec = *s.recipe.layout;
    const auto entries = make_legend(d, spec);
    for (const LegendEntry& e : entries)
      legend.push_back({{"value", e.value}, {"label", e.label}, {"colour", hex_colour(e.colour)}});
    const bool line = spec.kind->dimension() == 1;
    j["layout"] = {
        {"element", std::string(spec.kind->element_noun())},
        {"cell_mm",
         {spec.module_w + spec.joint, line ? spec.module_h : spec.module_h + spec.joint}},
        {"has_value_colours", !spec.value_colours.empty()}};
    if (spec.size) {
      const auto need = elements_to_cover(spec);
      j["layout"]["size_mm"] = {(*spec.size)[0], (*spec.size)[1]};
      j["layout"]["segment_cells"] = {need[0], need[1]};
      if (spec.kind->dimension() == 2) j["layout"]["surface"] = surface_json(spec);
    }
  } else {
    const auto colours = value_colours(d.curds);
    for (uint32_t v = 0; v < colours.size(); ++v)
      legend.push_back({{"value", v}, {"label", value_label(v, d.curds)}, {"colour", hex_colour(colours[v])}});
    j["layout"] = nullptr;
  }
  j["legend"] = legend;
  // What this recipe can download, from the registry: the page lists no names of its own.
  j["downloads"] = downloads(s.recipe.layout.has_value());
  return j;
}

ApiResponse json_response(const ordered_json& j) {
  ApiResponse r;
  r.body = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return r;
}

template <class F>
ApiResponse guarded(F&& f) {
  try {
    return f();
  } catch (const ResourceLimitError& e) {
    return api_error(413, render_error(e, query_key));
  } catch (const InputError& e) {
    return api_error(400, render_error(e, query_key));
  } catch (const std::bad_alloc&) {
    return api_error(507, "out of memory; try a smaller field or window");
  } catch (const std::exception& e) {
    return api_error(500, std::string("internal error: ") + e.what());
  }
}

const char* content_type(const std::string& name) {
  const std::string ext = fs::path(name).extension().string();
  if (ext == ".json") return "application/json";
  if (ext == ".csv") return "text/csv; charset=utf-8";
  if (ext == ".png") return "image/png";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".glb") return "model/gltf-binary";
  if (ext == ".toml") return "application/toml; charset=utf-8";
  if (ext == ".pdf") return "application/pdf";
  return "application/octet-stream";
}

}  // namespace

ApiResponse api_error(int status, const std::string& message) {
  ApiResponse r;
  r.status = status;
  // A message may quote bytes a caller sent that are not UTF-8: replaced, never thrown on.
  r.body = ordered_json{{"error", message}, {"status", status}}.dump(
      -1, ' ', false, nlohmann::json::error_handler_t::replace);
  return r;
}

ApiResponse api_recipe(const ApiContext& c) {
  return guarded([&] {
    const app::Run s = run_for(c, RunRequest{});
    ordered_json j = describe(s);
    j["seed"] = std::to_string(s.seed);
    j["recipe_toml"] = c.recipe_text;
    j["max_upload_bytes"] = c.limits.max_upload_bytes;
    return json_response(j);
  });
}

ApiResponse api_generate(const ApiContext& c, const Params& params) {
  return guarded([&] {
    const auto start = std::chrono::steady_clock::now();
    const RunRequest r = read_run(params, {"cells"});
    const std::string cells = own(r, "cells", "1");
    if (cells != "0" && cells != "1") throw InputError(parameter("cells"), "must be 0 or 1");
    const app::Run s = run_for(c, r);
    const Design& d = s.recipe.design;
    const int E = d.lattice.dimension;
    // The page sees the whole field unless it asks for a window.
    const Box view = r.window.empty() ? d.field : s.view;
    check_cells(d, view, c.limits.max_cells, "this request would generate");
    const CurdField field = curdle(d, s.seed, view, s.generate);
    const Report report = make_report(d, s.seed, field, view);
    ordered_json j = describe(s);
    j["seed"] = std::to_string(s.seed);
    j["view"] = box_json(view, E);
    j["report"] = report_to_json(report);
    if (cells == "1" && E <= 2) {
      const std::vector<uint16_t> values = values_in(field, view);
      if (d.curds.size() <= 8) {
        std::vector<uint8_t> bytes(values.begin(), values.end());
        j["values"] = base64(bytes.data(), bytes.size());
        j["value_bytes"] = 1;
      } else {
        j["values"] = base64(reinterpret_cast<const uint8_t*>(values.data()), values.size() * 2);
        j["value_bytes"] = 2;
      }
    }
    j["command"] = app::generate_command(s);
    j["server_ms"] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return json_response(j);
  });
}

ApiResponse api_export(const ApiContext& c, const Params& params) {
  return guarded([&] {
    const RunRequest r = read_run(params, {"file"});
    const std::string name = own(r, "file");
    // Every download is named here; one a layout-less recipe lacks is refused as such below.
    const std::vector<std::string> allowed = downloads(true);
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
      std::string list;
      for (const auto& n : allowed) list += (list.empty() ? "" : ", ") + n;
      throw InputError(parameter("file"), "'" + name + "' is not a download; allowed: " + list);
    }
    const app::Run s = run_for(c, r);
    const Design& d = s.recipe.design;
    const app::Output* output = app::find_output(name);
    const bool layout_file = output && output->needs_layout;
    check_cells(d, s.view, layout_file ? c.limits.max_layout_cells : c.limits.max_cells,
                layout_file ? "this layout would have" : "this request would generate");
    ApiResponse out;
    out.filename = name;
    out.content_type = content_type(name);
    if (name == "recipe.toml") {
      out.body = app::reproducing_recipe(s);
      return out;
    }
    const auto outputs = app::select_outputs(s, {name}, nullptr);
    app::MemorySink sink;
    app::write_outputs(s, outputs, sink, 0, nullptr);
    out.body = sink.files().at(name);
    return out;
  });
}

ApiResponse api_search(const ApiContext& c, const Params& params) {
  return guarded([&] {
    const auto start = std::chrono::steady_clock::now();
    RunRequest r = read_run(params, {"seeds", "target", "top", "stride", "segment"});
    // A search's window is a segment size, not a place: take it as `segment`.
    if (!r.window.empty())
      throw InputError(parameter("window"),
                       "a search takes segment=W,H (the size of the segments tried), not window");
    auto integer = [&](const std::string& key, int64_t fallback, int64_t lo, int64_t hi) {
      const std::string text = own(r, key);
      if (text.empty()) return fallback;
      const auto v = whole_number(text);
      if (!v || *v < lo || *v > hi)
        throw InputError(parameter(key), "must be a whole number from " + std::to_string(lo) +
                                             " to " + std::to_string(hi));
      return *v;
    };
    app::SearchRequest request;
    request.run = run_request(c, r);
    request.seeds = own(r, "seeds", "1..1000");
    request.segment = own(r, "segment");
    request.top = static_cast<int>(integer("top", 10, 1, 100));
    request.max_work = c.limits.max_search_work;
    request.stride = integer("stride", 0, 1, 1 << 20);
    const auto targets_it = r.own.find("target");
    if (targets_it != r.own.end()) request.targets = targets_it->second;
    const app::SearchRun search = app::resolve_search(request);
    const Design& d = search.run.recipe.design;
    const uint64_t first = search.first, last = search.last;
    check_cells(d, d.field, c.limits.max_cells, "each seed would generate");
    const auto hits = app::run_search(search, {}, c.stopping);
    ordered_json j = app::search_hits_json(search, hits);
    j["seeds"] = {std::to_string(first), std::to_string(last)};
    j["server_ms"] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return json_response(j);
  });
}

ApiResponse api_measure(const ApiContext& c, const Params& params, const std::string& body) {
  return guarded([&] {
    const RunRequest r = read_run(params, {"name", "base", "stages", "curds"});
    if (!r.sets.empty() || !r.seed.empty() || !r.window.empty())
      throw InputError(parameter("set"),
                       "a measure takes name, base, stages and curds only; the recipe is not run");
    const Lattice lattice = run_for(c, RunRequest{}).recipe.design.lattice;
    auto integer = [&](const std::string& key, int fallback) {
      const std::string text = own(r, key);
      if (text.empty()) return fallback;
      const auto v = whole_number(text);
      if (!v || *v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max())
        throw InputError(parameter(key), "'" + text + "' is not a whole number");
      return static_cast<int>(*v);
    };
    app::PictureStudyRequest request;
    request.bytes = body;
    request.name = own(r, "name", "picture");
    request.base = integer("base", lattice.base);
    request.stages = integer("stages", lattice.stages);
    request.curds = integer("curds", 1);
    // A fitted recipe this server could not generate is no use to the page.
    request.max_pixels = c.limits.max_cells;
    request.max_memory = memory_limit(c);
    const app::PictureStudy study = app::study_picture(request);
    const app::FittedRecipe& f = study.fitted;
    ordered_json curds = ordered_json::array();
    for (const app::FittedCurd& curd : f.curds) {
      ordered_json probabilities = ordered_json::array(), stages = ordered_json::array();
      for (const StageFit& s : curd.stages) {
        probabilities.push_back(app::probability_text(s.probability));
        stages.push_back({{"stage", s.stage},
                          {"measured", s.measured},
                          {"expected", s.expected},
                          {"probability", s.probability},
                          {"sd", s.sd}});
      }
      curds.push_back({{"name", curd.name},
                       {"colour", curd.colour},
                       {"probabilities", probabilities},
                       {"stages", stages}});
    }
    ordered_json j;
    j["measure"] = measure_to_json(study.measured);
    j["fit"] = {{"name", f.name},
                {"lattice",
                 {{"base", f.lattice.base},
                  {"dimension", f.lattice.dimension},
                  {"stages", f.lattice.stages},
                  {"mode", std::string(to_string(f.lattice.mode))}}},
                {"field", {f.size[0], f.size[1]}},
                {"curds", curds},
                {"recipe_toml", f.toml}};
    return json_response(j);
  });
}

ApiResponse api_colours(const Params& params) {
  return guarded([&] {
    std::vector<CurdSpec> curds;
    for (const auto& [key, value] : params) {
      if (key != "colour")
        throw InputError(parameter(key), "unknown parameter; allowed: colour (one per curd)");
      const auto colour = parse_hex_colour(value);
      if (!colour)
        throw InputError(parameter("colour"), "'" + value + "' is not a colour written #rrggbb");
      CurdSpec curd;
      curd.colour = colour;
      curds.push_back(curd);
    }
    if (curds.empty() || curds.size() > 8)
      throw InputError(parameter("colour"), "give from 1 to 8 curd colours");
    ordered_json values = ordered_json::array();
    for (const Rgb& c : value_colours(curds)) values.push_back(hex_colour(c));
    return json_response({{"values", values}});
  });
}

}  // namespace curdle::server
