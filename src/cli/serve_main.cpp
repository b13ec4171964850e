// curdle-serve: `curdle serve` as a program of its own, so that only it loads the HTTP server
// and its libraries. Run through `curdle serve`, which checks the options first.
#include <CLI/CLI.hpp>

#include "cli/exit_code.h"
#include "cli/serve_command.h"

int main(int argc, char** argv) {
  CLI::App app{"curdle serve: the interactive page on a local address"};
  curdle::cli::ServeOptions options;
  curdle::cli::add_serve_options(app, options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  return curdle::cli::exit_code([&] { return curdle::cli::run_serve(options); });
}
