// The JSON API of `curdle serve`, without HTTP: each endpoint is a function from query
// parameters to a response, so the benchmark and the tests can call it directly. Runs go
// through the same session and output code as the command line, so a download is the file
// `curdle generate` writes for the same recipe, seed and window.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <string>

namespace curdle::server {

using Params = std::multimap<std::string, std::string>;

struct ApiLimits {
  uint64_t max_cells = uint64_t{1} << 22;          // cells generated for one request (2048^2)
  uint64_t max_layout_cells = uint64_t{1} << 20;   // cells laid out for a layout download
  uint64_t max_search_work = uint64_t{1} << 30;    // seeds x field cells x stages, one search
  uint64_t max_memory = 0;                         // bytes a request may use; 0: a default
  uint64_t max_upload_bytes = uint64_t{16} << 20;  // a picture's file sent to be measured
};

struct ApiContext {
  std::string recipe_path;  // as given to `serve`; named in commands
  std::string recipe_text;  // read once at start
  ApiLimits limits;
  const std::atomic<bool>* stopping = nullptr;  // set on shutdown: long searches end early
};

// The API's JSON answers: UTF-8, never compressed (the page and its API share one machine).
inline constexpr const char* kJsonType = "application/json; charset=utf-8";

struct ApiResponse {
  int status = 200;
  // Never compressed, as no answer is (server.cpp): brotli took 0.26 s of a page-sized
  // generate's 0.26 s over loopback (90 KB of JSON; 4 ms without it).
  std::string content_type = kJsonType;
  std::string body;
  std::string filename;  // set for downloads
};

// GET /api/recipe: the recipe as the page needs it (lattice, curds, field, layout, legend),
// and the largest picture the page may send.
ApiResponse api_recipe(const ApiContext& context);
// GET /api/generate: seed, window, cells=0|1 and recipe keys (lattice.base=3, or
// set=lattice.base=3): report, legend, values of the cells, command and recipe text.
ApiResponse api_generate(const ApiContext& context, const Params& params);
// GET /api/field: as generate with cells=1, for the page's canvas: the body is binary, so that
// nothing encodes, compresses or parses the cells on the way:
//   "CRD1", then n (uint32, little-endian), then n bytes of JSON: generate's answer without
//   "values", with "value_bits" (1, 2, 4, 8 or 16 bits a cell; 0 on a 3-D lattice), padded
//   with spaces to a multiple of four; then the values packed (curdle/packed_values.h): row
//   by row from the view's corner, x fastest, cell i at bit i * value_bits, lowest first.
inline constexpr const char* kFieldMagic = "CRD1";
ApiResponse api_field(const ApiContext& context, const Params& params);
// Whether a generate is as light as the page's own (a field of at most kLightCells cells, or
// a request refused at once): the server runs those in a slot of their own.
inline constexpr uint64_t kLightCells = uint64_t{1} << 18;
bool api_generate_is_light(const ApiContext& context, const Params& params);
// GET /api/export: as generate, plus file=NAME; the file `curdle generate` writes.
ApiResponse api_export(const ApiContext& context, const Params& params);
// GET /api/search: seeds=A..B, window=W,H, target (repeatable), top, stride, recipe keys.
ApiResponse api_search(const ApiContext& context, const Params& params);

// POST /api/measure: the body is a picture's file; name (its file name), base, stages and
// curds (default: the recipe's). The picture measured (measure.json's content) and a recipe
// fitted to it, whose probabilities the page loads as overrides.
ApiResponse api_measure(const ApiContext& context, const Params& params, const std::string& body);

// POST /api/site: the body is a site drawing (DXF or SVG); name (its file name), and once the
// layers are chosen outline, openings and zones (repeatable) and units, with the page's recipe
// keys. Its layers, and the surface read from it as overrides (app/site_study.h).
ApiResponse api_site(const ApiContext& context, const Params& params, const std::string& body);

// GET /api/colours: colour=#rrggbb once per curd; the colour of every value as the library
// blends it ({"values": [...]}, value 0 first), so that the page never blends on its own.
ApiResponse api_colours(const Params& params);

// {"error": message} with an HTTP status.
ApiResponse api_error(int status, const std::string& message);

}  // namespace curdle::server
