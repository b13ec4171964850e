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
#include "app/page.h"
#include "app/picture_study.h"
#include "app/reproduce.h"
#include "app/run.h"
#include "app/search_run.h"
#include "app/site_study.h"
#include "app/stopping.h"
#include "curdle/error.h"

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace curdle::server {
namespace {

// The API spells a run parameter as its query key; an override is named by its recipe key.
std::string query_key(const std::string& parameter) {
  return parameter == "set" ? std::string() : parameter + "=";
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
  // Paths name files on the server's disk: a request may not point them elsewhere, and their
  // messages would tell whether a path exists there. The recipe's own are used.
  for (const std::string& set : r.sets)
    if (app::set_names_a_file(set))
      throw InputError(parameter("set", set.substr(0, set.find('='))),
                       "names a file on the server, which requests may not set; the recipe's "
                       "own file is used");
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

ApiResponse json_response(const ordered_json& j) {
  ApiResponse r;
  r.body = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return r;
}

// An answer names the recipe by its file name alone: where the server keeps its files is no
// client's business.
std::string answer_text(const InputError& e) {
  SourceLocation where = e.where();
  where.file = fs::path(where.file).filename().string();
  return render_error(InputError(where, e.message()), query_key);
}

template <class F>
ApiResponse guarded(F&& f) {
  try {
    return f();
  } catch (const app::WorkStopped& e) {
    return api_error(503, e.what());
  } catch (const ResourceLimitError& e) {
    return api_error(413, answer_text(e));
  } catch (const InputError& e) {
    return api_error(400, answer_text(e));
  } catch (const std::bad_alloc&) {
    return api_error(507,
                     "out of memory: the request needs more memory than the server may use; ask "
                     "for a smaller field, window, layout or picture, or start the server with a "
                     "larger --max-memory");
  } catch (const std::exception& e) {
    return api_error(500, std::string("internal error: ") + e.what());
  }
}

const char* content_type(const std::string& name) {
  const std::string ext = fs::path(name).extension().string();
  if (ext == ".json") return kJsonType;
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
    ordered_json j = app::describe_run(s);
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
    // The page sees the whole field unless it asks for a window.
    const Box view = r.window.empty() ? d.field : s.view;
    app::check_cells(d, view, c.limits.max_cells, "this request would generate");
    ordered_json j = app::segment_json(s, view, cells == "1");
    j["command"] = app::generate_command(s);
    j["server_ms"] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return json_response(j);
  });
}

ApiResponse api_field(const ApiContext& c, const Params& params) {
  return guarded([&] {
    const auto start = std::chrono::steady_clock::now();
    const RunRequest r = read_run(params, {});
    const app::Run s = run_for(c, r);
    const Box view = r.window.empty() ? s.recipe.design.field : s.view;
    app::check_cells(s.recipe.design, view, c.limits.max_cells, "this request would generate");
    app::PageField field = app::page_field(s, view);
    field.head["command"] = app::generate_command(s);
    field.head["server_ms"] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::string head = field.head.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    head.append((4 - head.size() % 4) % 4, ' ');
    ApiResponse out;
    out.content_type = "application/octet-stream";
    out.body.reserve(8 + head.size() + field.values.size());
    out.body.append(kFieldMagic, 4);
    const uint32_t n = static_cast<uint32_t>(head.size());
    for (int k = 0; k < 4; ++k) out.body.push_back(static_cast<char>((n >> (8 * k)) & 0xff));
    out.body += head;
    out.body += field.values;
    return out;
  });
}

bool api_generate_is_light(const ApiContext& c, const Params& params) {
  try {
    const RunRequest r = read_run(params, {"cells"});
    // Sized on the connection's thread from the text alone: its pictures and drawings are
    // read in the slot it is given, within the limit on work at once.
    app::RunRequest request = run_request(c, r);
    request.read_files = false;
    const app::Run s = app::resolve_run(request);
    const Box view = r.window.empty() ? s.recipe.design.field : s.view;
    return view.cells() <= kLightCells;
  } catch (const app::FilesNeeded&) {
    return false;  // sized by a drawing: a heavy slot
  } catch (const std::exception&) {
    return true;  // its error is answered at once
  }
}

ApiResponse api_export(const ApiContext& c, const Params& params) {
  return guarded([&] {
    const RunRequest r = read_run(params, {"file"});
    const std::string name = own(r, "file");
    // Every download is named here; one a layout-less recipe lacks is refused as such below.
    const std::vector<std::string> allowed = app::page_downloads(true);
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
      std::string list;
      for (const auto& n : allowed) list += (list.empty() ? "" : ", ") + n;
      throw InputError(parameter("file"), "'" + name + "' is not a download; allowed: " + list);
    }
    const app::Run s = run_for(c, r);
    const Design& d = s.recipe.design;
    const app::Output* output = app::find_output(name);
    const bool layout_file = output && output->needs_layout;
    app::check_cells(d, s.view, layout_file ? c.limits.max_layout_cells : c.limits.max_cells,
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
    app::check_cells(d, d.field, c.limits.max_cells, "each seed would generate");
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
    const RunRequest r = read_run(params, {"name", "base", "stages", "curds", "states"});
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
    request.states = integer("states", 0);
    // A fitted recipe this server could not generate is no use to the page.
    request.max_pixels = c.limits.max_cells;
    request.max_memory = memory_limit(c);
    const app::PictureStudy study = app::study_picture(request);
    return json_response(app::picture_study_json(study));
  });
}

ApiResponse api_site(const ApiContext& c, const Params& params, const std::string& body) {
  return guarded([&] {
    const RunRequest r =
        read_run(params, {"name", "outline", "around", "openings", "zones", "units"});
    app::SiteStudyRequest request;
    request.bytes = body;
    request.name = app::upload_name(own(r, "name", "site.dxf"));
    request.outline = own(r, "outline");
    request.around = own(r, "around");
    request.units = own(r, "units");
    if (const auto it = r.own.find("openings"); it != r.own.end()) request.openings = it->second;
    if (const auto it = r.own.find("zones"); it != r.own.end()) request.zones = it->second;
    // The page's run as it stands (its lattice, kind and overrides) takes the site.
    RunRequest run = r;
    run.own.clear();
    return json_response(app::study_site(run_for(c, run), request));
  });
}

ApiResponse api_colours(const Params& params) {
  return guarded([&] {
    std::vector<std::string> colours;
    for (const auto& [key, value] : params) {
      if (key != "colour")
        throw InputError(parameter(key), "unknown parameter; allowed: colour (one per curd)");
      colours.push_back(value);
    }
    return json_response(app::value_colours_json(colours));
  });
}

}  // namespace curdle::server
