// `curdle serve`: the interactive page on a local address, until Ctrl-C. The server and the
// libraries only it needs (HTTP, TLS, compression) are a program of their own, curdle-serve,
// which `curdle serve` executes: every other command starts without loading them.
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
  int request_seconds = 60;
  uint64_t max_cells = uint64_t{1} << 22;
  std::string max_memory;
};

inline constexpr const char* kDefaultPattern = "paper/fig8-segment-of-large-curd.toml";

void add_serve_options(CLI::App& command, ServeOptions& options);
// Runs the server (in curdle-serve).
int run_serve(const ServeOptions& options);
// Replaces this process with curdle-serve beside it, passing the arguments after "serve";
// returns only on failure.
int exec_serve(int argc, char** argv);

}  // namespace curdle::cli
