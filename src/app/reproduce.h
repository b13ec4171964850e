// What reproduces a run: the `curdle generate` command line, and the recipe with every
// override, the seed and the window written in.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/run.h"

namespace curdle::app {

// "X,Y,W,H" (1-D "X,W"; 3-D "X,Y,Z,W,H,D"), as a window is written.
std::string window_text(const Box& window, int dimension);

// The `curdle generate` command line that reproduces a run exactly, quoted for a POSIX shell.
std::string generate_command(const std::string& recipe_path, const std::vector<std::string>& sets,
                             uint64_t seed, const std::optional<Box>& window, int dimension);
// The same for a resolved run: its window only when the request gave one.
std::string generate_command(const Run& run);

// The recipe's TOML with the run's overrides, seed and window written in: it reproduces the
// run with no options at all.
std::string reproducing_recipe(const Run& run);

}  // namespace curdle::app
