// Fuzz target: the API's query handling. Input: a request target ("/api/generate?seed=3&...");
// its query is split and decoded as the server does and sent to the endpoint its path names,
// over a small fixed recipe with small limits. Every answer must be JSON with a status; none
// may crash or hang.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "server/api.h"
#include "server/server.h"

namespace {

const char* kRecipe = R"(name = "fuzz"
[lattice]
base = 2
dimension = 2
[[curds]]
name = "dark"
probabilities = ["3/4", "2/3", "1/2"]
[field]
cells = [16, 16]
[layout]
kind = "paving"
tile = [300, 300]
joint = 5
floor = [2400, 2400]
)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 8 * 1024) return 0;
  const std::string target(reinterpret_cast<const char*>(data), size);
  curdle::server::ApiContext context;
  context.recipe_path = "fuzz.toml";
  context.recipe_text = kRecipe;
  context.limits.max_cells = 1 << 14;
  context.limits.max_layout_cells = 1 << 12;
  context.limits.max_search_work = 1 << 20;
  context.limits.max_memory = uint64_t{64} << 20;
  const curdle::server::Params params = curdle::server::query_params(target);
  const std::string path = target.substr(0, target.find('?'));
  curdle::server::ApiResponse r;
  if (path == "/api/recipe")
    r = curdle::server::api_recipe(context);
  else if (path == "/api/colours")
    r = curdle::server::api_colours(params);
  else if (path == "/api/export")
    r = curdle::server::api_export(context, params);
  else if (path == "/api/search")
    r = curdle::server::api_search(context, params);
  else
    r = curdle::server::api_generate(context, params);
  if (r.status < 200 || r.status > 599) __builtin_trap();
  if (r.status != 200 || r.content_type == curdle::server::kJsonType)
    if (!nlohmann::json::accept(r.body)) __builtin_trap();  // an answer the page can read
  return 0;
}
