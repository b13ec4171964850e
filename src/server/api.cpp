#include "server/api.h"

#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "cli/generate.h"
#include "cli/search_command.h"
#include "cli/session.h"
#include "curdle/curdling.h"
#include "curdle/error.h"
#include "curdle/overlay.h"
#include "curdle/palette.h"
#include "curdle/report.h"
#include "export/report_json.h"
#include "layout/builder.h"

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace curdle::server {
namespace {

// A request over a limit: 413, with what is allowed.
struct TooLarge : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const std::set<std::string> kDownloads = {"report.json",  "cells.csv",      "preview.png",
                                          "layout.svg",   "layout.png",     "layout.glb",
                                          "schedule.csv", "quantities.csv", "install.svg",
                                          "recipe.toml"};

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
    throw TooLarge("too many parameters (" + std::to_string(params.size()) + "); at most 256");
  RunRequest r;
  for (const auto& [key, value] : params) {
    if (key == "set") {
      if (value.find('=') == std::string::npos)
        throw InputError(SourceLocation{"set", 0, 0, ""},
                         "'" + value + "' is not KEY=VALUE, e.g. set=lattice.base=3");
      r.sets.push_back(value);
    } else if (key.find('.') != std::string::npos) {
      r.sets.push_back(key + "=" + value);
    } else if (key == "seed") {
      r.seed = value;
    } else if (key == "window") {
      r.window = value;
    } else if (own_names.count(key)) {
      r.own[key].push_back(value);
    } else {
      std::string allowed = "seed, window, set";
      for (const auto& n : own_names) allowed += ", " + n;
      throw InputError(SourceLocation{key, 0, 0, ""},
                       "unknown parameter; allowed: " + allowed +
                           ", and recipe keys such as lattice.base=3 or curds.0.probabilities=[\"1/2\",\"1/2\"]");
    }
  }
  return r;
}

std::string own(const RunRequest& r, const std::string& name, const std::string& fallback = "") {
  const auto it = r.own.find(name);
  return it == r.own.end() ? fallback : it->second.back();
}

uint64_t memory_limit(const ApiContext& c) {
  return c.limits.max_memory ? c.limits.max_memory : cli::default_memory_limit() / 4;
}

cli::Session session_for(const ApiContext& c, const RunRequest& r) {
  cli::CommonOptions o;
  o.recipe_path = c.recipe_path;
  o.seed = r.seed;
  o.sets = r.sets;
  o.window = r.window;
  cli::Session s = cli::make_session(c.recipe_text, o);
  s.generate.max_memory_bytes = memory_limit(c);
  s.generate.memory_limit_hint = "start the server with a larger --max-memory";
  return s;
}

void check_cells(const Design& d, const Box& view, uint64_t limit, const char* what) {
  const uint64_t cells = generation_box(d, view).cells();
  if (cells > limit)
    throw TooLarge(std::string(what) + " " + std::to_string(cells) + " cells; the server allows " +
                   std::to_string(limit) +
                   ": choose a smaller field.cells or window, or start it with a larger "
                   "--max-cells");
}

ordered_json box_json(const Box& b, int dimension) {
  ordered_json j = ordered_json::array();
  for (int d = 0; d < dimension; ++d) j.push_back(b.origin[d]);
  for (int d = 0; d < dimension; ++d) j.push_back(b.size[d]);
  return j;
}

// What the page draws and edits: the design, layout facts and the legend.
ordered_json describe(const cli::Session& s) {
  const Design& d = s.recipe.design;
  const int E = d.lattice.dimension;
  ordered_json j;
  j["name"] = d.name;
  j["description"] = s.recipe.description;
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
    const bool line = spec.kind == LayoutKind::rhythm;
    j["layout"] = {{"element", element_type(spec.kind)},
                   {"cell_mm", {spec.module_w + spec.joint, line ? spec.module_h : spec.module_h + spec.joint}},
                   {"has_value_colours", !spec.value_colours.empty()}};
    if (spec.size) {
      const auto need = elements_to_cover(spec);
      j["layout"]["size_mm"] = {(*spec.size)[0], (*spec.size)[1]};
      j["layout"]["segment_cells"] = {need[0], need[1]};
    }
  } else {
    const auto colours = value_colours(d.curds);
    for (uint32_t v = 0; v < colours.size(); ++v)
      legend.push_back({{"value", v}, {"label", value_label(v, d.curds)}, {"colour", hex_colour(colours[v])}});
    j["layout"] = nullptr;
  }
  j["legend"] = legend;
  return j;
}

ApiResponse json_response(const ordered_json& j) {
  ApiResponse r;
  r.body = j.dump();
  return r;
}

template <class F>
ApiResponse guarded(F&& f) {
  try {
    return f();
  } catch (const TooLarge& e) {
    return api_error(413, e.what());
  } catch (const InputError& e) {
    return api_error(400, e.what());
  } catch (const std::bad_alloc&) {
    return api_error(507, "out of memory; try a smaller field or window");
  } catch (const std::exception& e) {
    return api_error(500, std::string("internal error: ") + e.what());
  }
}

// A fresh private directory for one download, removed when done.
struct ScratchDir {
  fs::path path;
  ScratchDir() {
    std::string pattern = (fs::temp_directory_path() / "curdle-serve-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot make a temporary directory");
    path = pattern;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const char* content_type(const std::string& name) {
  const std::string ext = fs::path(name).extension().string();
  if (ext == ".json") return "application/json";
  if (ext == ".csv") return "text/csv; charset=utf-8";
  if (ext == ".png") return "image/png";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".glb") return "model/gltf-binary";
  if (ext == ".toml") return "application/toml; charset=utf-8";
  return "application/octet-stream";
}

}  // namespace

ApiResponse api_error(int status, const std::string& message) {
  ApiResponse r;
  r.status = status;
  r.body = ordered_json{{"error", message}, {"status", status}}.dump();
  return r;
}

ApiResponse api_recipe(const ApiContext& c) {
  return guarded([&] {
    const cli::Session s = session_for(c, RunRequest{});
    ordered_json j = describe(s);
    j["seed"] = s.seed;
    j["recipe_toml"] = c.recipe_text;
    return json_response(j);
  });
}

ApiResponse api_generate(const ApiContext& c, const Params& params) {
  return guarded([&] {
    const auto start = std::chrono::steady_clock::now();
    const RunRequest r = read_run(params, {"cells"});
    const std::string cells = own(r, "cells", "1");
    if (cells != "0" && cells != "1")
      throw InputError(SourceLocation{"cells", 0, 0, ""}, "must be 0 or 1");
    cli::Session s = session_for(c, r);
    const Design& d = s.recipe.design;
    const int E = d.lattice.dimension;
    // The page sees the whole field unless it asks for a window.
    const Box view = r.window.empty() ? d.field : s.view;
    check_cells(d, view, c.limits.max_cells, "this request would generate");
    const CurdField field = curdle(d, s.seed, view, s.generate);
    const Report report = make_report(d, s.seed, field, view);
    ordered_json j = describe(s);
    j["seed"] = s.seed;
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
    const std::optional<Box> window =
        r.window.empty() ? std::nullopt : std::optional<Box>(view);
    j["command"] = cli::generate_command(c.recipe_path, r.sets, s.seed, window, E);
    j["server_ms"] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return json_response(j);
  });
}

ApiResponse api_export(const ApiContext& c, const Params& params) {
  return guarded([&] {
    const RunRequest r = read_run(params, {"file"});
    const std::string name = own(r, "file");
    if (!kDownloads.count(name)) {
      std::string allowed;
      for (const auto& n : kDownloads) allowed += (allowed.empty() ? "" : ", ") + n;
      throw InputError(SourceLocation{"file", 0, 0, ""},
                       "'" + name + "' is not a download; allowed: " + allowed);
    }
    cli::Session s = session_for(c, r);
    const Design& d = s.recipe.design;
    const bool layout_file = name != "report.json" && name != "cells.csv" &&
                             name != "preview.png" && name != "recipe.toml";
    check_cells(d, s.view, layout_file ? c.limits.max_layout_cells : c.limits.max_cells,
                layout_file ? "this layout would have" : "this request would generate");
    ApiResponse out;
    out.filename = name;
    out.content_type = content_type(name);
    if (name == "recipe.toml") {
      // The recipe with every change, the seed and the window written in: it reproduces the
      // run with no options at all.
      std::vector<std::string> sets = r.sets;
      sets.push_back("seed=" + std::to_string(s.seed));
      if (!r.window.empty() || s.recipe.window) {
        std::string w = "field.window=[" + cli::window_text(s.view, d.lattice.dimension) + "]";
        sets.push_back(w);
      }
      out.body = recipe_text_with(c.recipe_text, c.recipe_path, sets);
      return out;
    }
    ScratchDir scratch;
    cli::write_outputs(s, scratch.path, {name}, 0, nullptr);
    out.body = read_file(scratch.path / name);
    return out;
  });
}

ApiResponse api_search(const ApiContext& c, const Params& params) {
  return guarded([&] {
    const auto start = std::chrono::steady_clock::now();
    RunRequest r = read_run(params, {"seeds", "target", "top", "stride", "segment"});
    // A search's window is a segment size, not a place: take it as `segment`.
    if (!r.window.empty())
      throw InputError(SourceLocation{"window", 0, 0, ""},
                       "a search takes segment=W,H (the size of the segments tried), not window");
    cli::Session s = session_for(c, r);
    const Design& d = s.recipe.design;
    const auto [first, last] = cli::parse_seed_range(own(r, "seeds", "1..1000"), "seeds");
    auto integer = [&](const std::string& key, int64_t fallback, int64_t lo, int64_t hi) {
      const std::string text = own(r, key);
      if (text.empty()) return fallback;
      int64_t v = 0;
      auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (ec != std::errc() || p != text.data() + text.size() || v < lo || v > hi)
        throw InputError(SourceLocation{key, 0, 0, ""},
                         "must be a whole number from " + std::to_string(lo) + " to " +
                             std::to_string(hi));
      return v;
    };
    const int top = static_cast<int>(integer("top", 10, 1, 100));
    const int64_t stride = integer("stride", 0, 1, 1 << 20);
    const auto targets_it = r.own.find("target");
    const std::vector<std::string> targets =
        targets_it == r.own.end() ? std::vector<std::string>{} : targets_it->second;
    const SearchSpec spec = cli::make_search_spec(s, targets, own(r, "segment"), stride, top, 0);
    check_cells(d, d.field, c.limits.max_cells, "each seed would generate");
    // Counted as last - first, which cannot overflow, against the most seeds of this field.
    const uint64_t most = c.limits.max_search_cells / std::max<uint64_t>(1, d.field.cells());
    if (last - first >= most)
      throw TooLarge("seeds " + std::to_string(first) + " to " + std::to_string(last) + " of " +
                     std::to_string(d.field.cells()) +
                     " cells are more than the server searches at once (" + std::to_string(most) +
                     " seeds of this field); search fewer seeds, or run curdle search");
    const auto hits = search_seeds(d, d.field, spec, first, last, {}, c.stopping);
    ordered_json j = cli::search_hits_json(s, r.sets, spec, hits);
    j["seeds"] = {first, last};
    j["server_ms"] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return json_response(j);
  });
}

}  // namespace curdle::server
