// A run: a recipe with the caller's overrides, seed, window and limits, resolved and checked.
// Both shells build a RunRequest from their own input (command-line options, query parameters)
// and get the same Run, so that the page's downloads are the command line's files.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "curdle/curdling.h"
#include "recipe/recipe.h"

namespace curdle::app {

struct RunRequest {
  std::string recipe_text;
  std::string recipe_path;             // names the recipe in messages and commands
  std::vector<std::string> overrides;  // "dotted.key=VALUE", as --set or API keys give them
  std::string seed;                    // empty: the recipe's seed
  std::string window;                  // empty: the recipe's window, else the whole field
  uint64_t max_memory = 0;             // bytes; 0: default_memory_limit()
  std::string memory_limit_hint;       // how this caller raises the limit, for messages
  // False: the recipe alone, for sizing a request before it may use memory; a recipe that
  // needs a drawing to be sized throws FilesNeeded, and density pictures are not decoded.
  bool read_files = true;
};

// A run resolved without its files (RunRequest::read_files) needed one to know its size.
class FilesNeeded : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Run {
  std::string recipe_path;
  std::string recipe_text;
  std::vector<std::string> overrides;
  Recipe recipe;
  uint64_t seed = 0;
  Box view;                   // the cells the outputs show
  bool window_given = false;  // by the request, not the recipe
  GenerateOptions generate;   // memory limit and hint
};

// Parses the recipe with the overrides and checks seed and window. Throws InputError naming
// the recipe key or the parameter ("seed", "window", "set").
Run resolve_run(const RunRequest& request);

// Whether an override (--set, an API key) names a file on the machine (recipe.h's
// override_names_a_file): a server refuses it, so that no request reads or probes its disk.
bool set_names_a_file(const std::string& assignment);

// The recipe file's text; InputError when it is not a readable regular file of at most 1 MiB.
std::string read_recipe_file(const std::string& path);

// "8G", "512M", "1.5GiB" or a number of bytes; InputError naming `parameter`.
uint64_t parse_bytes(const std::string& text, const std::string& parameter);
// Half the physical memory.
uint64_t default_memory_limit();

// Runs the engine over the run's view with at most `threads` threads (0: all cores).
CurdField run_engine(const Run& run, int threads, const std::function<void(double)>& progress = {});

// Starts the engine's worker threads in the background, so that a short-lived process does
// not wait for them at its first parallel stage (about a millisecond, a tenth of a small run).
void start_worker_threads(int threads);

}  // namespace curdle::app
