// `curdle search`: many seeds of a recipe ranked by how well their segments meet targets,
// the best printed with their scores and the command that reproduces each, their previews and
// a CSV of all written.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace curdle::cli {

struct SearchOptions {
  std::string recipe_path;
  std::vector<std::string> sets;
  std::string seeds;   // "A..B", inclusive, or one seed
  std::string window;  // "W,H" (1-D: "W"): segment size in cells
  int64_t stride = 0;
  std::vector<std::string> targets;
  int top = 10;
  int64_t lacunarity_box = 0;
  std::string out_dir;
  bool previews = true;
  int threads = 0;
  std::string max_memory;
};

void add_search_options(CLI::App& command, SearchOptions& options);
int run_search(const SearchOptions& options);

}  // namespace curdle::cli
