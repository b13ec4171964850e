// curdle: random curds for façades, paving, perforated panels and parks.
// Exceptions become exit codes here and only here: 2 for bad input, 1 for internal failure.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "cli/exit_code.h"
#include "cli/fit_command.h"
#include "cli/generate_command.h"
#include "cli/interrupt.h"
#include "cli/measure_command.h"
#include "cli/memory_reuse.h"
#include "cli/options.h"
#include "cli/search_command.h"
#include "cli/serve_command.h"
#include "curdle/error.h"

namespace fs = std::filesystem;

namespace curdle::cli {
namespace {

int run(int argc, char** argv) {
  CLI::App app{
      "curdle: random curds (Mandelbrot curdling, overlaid after Cirovic 2014) "
      "for facade, paving, perforation and park layouts"};
  app.require_subcommand(1);
  // The project's version (CMakeLists.txt's project(), the one place it is written), as the
  // library and the Python module's __version__ give it.
  app.set_version_flag("--version", std::string("curdle ") + CURDLE_VERSION +
                                        " (GPL-3.0-or-later; see LICENSE and THIRD-PARTY-NOTICES)");

  CommonOptions gen_options, report_options;
  std::string out_dir;
  std::vector<std::string> outputs;
  CLI::App* gen = app.add_subcommand("generate", "Curdle a recipe and write its outputs");
  add_common_options(*gen, gen_options);
  gen->add_option("--out", out_dir, "Output directory (default: curdle-out/<recipe name>)")
      ->check(kNotEmpty);
  gen->add_option("--outputs", outputs, outputs_help())->delimiter(',');
  CLI::App* rep = app.add_subcommand("report", "Print the per-stage report of a recipe");
  add_common_options(*rep, report_options);
  SearchOptions search_options;
  CLI::App* find = app.add_subcommand(
      "search", "Rank seeds, and segments of each seed's curd, by how well they meet targets");
  add_search_options(*find, search_options);

  MeasureOptions measure_options;
  CLI::App* meas = app.add_subcommand(
      "measure", "Measure a picture: each value's share, lacunarity and box-counting dimension");
  add_measure_options(*meas, measure_options);

  FitOptions fit_options;
  CLI::App* fit = app.add_subcommand(
      "fit", "Fit a recipe to a picture: per-stage probabilities that give its statistics");
  add_fit_options(*fit, fit_options);

  ServeOptions serve_options;
  CLI::App* serve = app.add_subcommand(
      "serve", "Serve the interactive page on a local address: edit, select segments, export");
  add_serve_options(*serve, serve_options);

  const std::string command = argc >= 2 ? argv[1] : "";
  if (argc >= 2 && argv[1][0] != '-' && command != "generate" && command != "report" &&
      command != "search" && command != "serve" && command != "measure" && command != "fit") {
    std::fprintf(stderr,
                 "curdle: error: unknown command '%s'; the commands are generate, report, "
                 "search, measure, fit and serve (curdle --help)\n",
                 argv[1]);
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  if (gen->parsed()) return run_generate(gen_options, out_dir, outputs);
  if (find->parsed()) return run_search(search_options);
  if (serve->parsed()) return exec_serve(argc, argv);
  if (meas->parsed()) return run_measure(measure_options);
  if (fit->parsed()) return run_fit(fit_options);
  return run_report(report_options);
}

}  // namespace
}  // namespace curdle::cli

int main(int argc, char** argv) {
  curdle::cli::keep_freed_memory_for_reuse();
  curdle::cli::remove_staged_files_on_interrupt();
  return curdle::cli::exit_code([&] { return curdle::cli::run(argc, argv); });
}
