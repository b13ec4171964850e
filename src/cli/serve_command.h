// `curdle serve`: the interactive page on a local address, until Ctrl-C.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace curdle::cli {

struct ServeOptions {
  std::string recipe_path;  // empty: the default pattern installed with the program
  std::string host = "127.0.0.1";
  int port = 8080;
  std::string web_root;
  int workers = 2;
  uint64_t max_cells = uint64_t{1} << 22;
  std::string max_memory;
};

void add_serve_options(CLI::App& command, ServeOptions& options);
int run_serve(const ServeOptions& options);

}  // namespace curdle::cli
