// What `generate` and `report` share: reading the recipe file, applying the command line's
// seed, window, overrides and limits, and running the engine.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "curdle/curdling.h"
#include "curdle/report.h"
#include "recipe/recipe.h"

namespace curdle::cli {

struct CommonOptions {
  std::string recipe_path;
  std::string seed;  // checked by open_session: a whole number from 0 to 2^64 - 1
  std::vector<std::string> sets;
  std::string window;
  int threads = 0;  // 0: all cores
  std::string max_memory;
};

void add_common_options(CLI::App& command, CommonOptions& options);

struct Session {
  std::string recipe_path;  // for messages, and the mask image beside the recipe
  Recipe recipe;
  uint64_t seed = 0;
  Box view;
  GenerateOptions generate;
};

// Reads and checks everything the command line names; throws InputError on bad input.
Session open_session(const CommonOptions& options);
// The same for a recipe already read (`options.recipe_path` names it).
Session make_session(const std::string& recipe_text, const CommonOptions& options);

// The recipe file's text; throws InputError when it cannot be read.
std::string read_recipe_file(const std::string& path);

// Runs the engine, honouring --threads, with progress on a terminal when `show_progress`.
CurdField run_engine(const Session& session, int threads, bool show_progress = true);

// "X,Y,W,H" (1-D "X,W"; 3-D "X,Y,Z,W,H,D"), as --window takes it.
std::string window_text(const Box& window, int dimension);

// The `curdle generate` command line that reproduces a run exactly, quoted for a POSIX shell.
std::string generate_command(const std::string& recipe_path, const std::vector<std::string>& sets,
                             uint64_t seed, const std::optional<Box>& window, int dimension);

// "8G", "512M", "1.5GiB" or a number of bytes.
uint64_t parse_bytes(const std::string& text, const std::string& option);
uint64_t default_memory_limit();

}  // namespace curdle::cli
