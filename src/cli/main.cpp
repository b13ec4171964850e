// curdle: random curds for façades, paving, perforated panels and parks.
// Exceptions become exit codes here and only here: 2 for bad input, 1 for internal failure.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <set>

#include "cli/session.h"
#include "curdle/error.h"
#include "curdle/report.h"
#include "export/atomic_file.h"
#include "export/cells_csv.h"
#include "export/preview_png.h"
#include "export/report_json.h"
#include "export/report_table.h"

namespace fs = std::filesystem;

namespace curdle::cli {
namespace {

constexpr uint64_t kCellsCsvDefaultLimit = 10'000'000;
const std::vector<std::string> kOutputs = {"report.json", "cells.csv", "preview.png"};

std::set<std::string> parse_outputs(const std::vector<std::string>& names) {
  std::set<std::string> chosen;
  for (std::string n : names) {
    if (n.find('.') == std::string::npos)
      for (const auto& o : kOutputs)
        if (o.rfind(n + ".", 0) == 0) n = o;
    if (std::find(kOutputs.begin(), kOutputs.end(), n) == kOutputs.end())
      throw InputError(SourceLocation{"--outputs", 0, 0, ""},
                       "unknown output '" + n + "'; allowed: report.json, cells.csv, preview.png");
    chosen.insert(n);
  }
  return chosen;
}

int generate(const CommonOptions& common, const std::string& out_dir,
             const std::vector<std::string>& outputs_named) {
  const Session s = open_session(common);
  std::set<std::string> outputs = outputs_named.empty()
                                      ? std::set<std::string>(kOutputs.begin(), kOutputs.end())
                                      : parse_outputs(outputs_named);
  const bool csv_named = outputs_named.size() && outputs.count("cells.csv");
  if (outputs.count("cells.csv") && !csv_named && s.view.cells() > kCellsCsvDefaultLimit) {
    outputs.erase("cells.csv");
    std::fprintf(stderr,
                 "note: cells.csv skipped: %llu cells is above %llu; name it with --outputs "
                 "cells.csv to write it anyway\n",
                 static_cast<unsigned long long>(s.view.cells()),
                 static_cast<unsigned long long>(kCellsCsvDefaultLimit));
  }
  const fs::path dir = out_dir.empty()
                           ? fs::path("curdle-out") / fs::path(common.recipe_path).stem()
                           : fs::path(out_dir);
  make_output_dir(dir);

  const CurdField field = run_engine(s, common.threads);
  const Report report = make_report(s.recipe.design, s.seed, field, s.view);

  std::vector<fs::path> written;
  if (outputs.count("report.json")) {
    write_file(dir / "report.json",
               [&](std::ostream& o) { o << report_to_json(report).dump(2) << "\n"; });
    written.push_back(dir / "report.json");
  }
  if (outputs.count("cells.csv")) {
    write_file(dir / "cells.csv",
               [&](std::ostream& o) { write_cells_csv(o, s.recipe.design, field, s.view); });
    written.push_back(dir / "cells.csv");
  }
  if (outputs.count("preview.png")) {
    write_png(dir / "preview.png", render_preview(s.recipe.design, field, s.view));
    written.push_back(dir / "preview.png");
  }
  std::printf("%s, seed %llu: %llu cells\n", s.recipe.design.name.c_str(),
              static_cast<unsigned long long>(s.seed),
              static_cast<unsigned long long>(report.cells));
  for (const CurdReport& c : report.curds)
    std::printf("  curd %-12s %llu survivors (expected %.1f), box dimension %s (theory %s)\n",
                c.name.c_str(), static_cast<unsigned long long>(c.stages.back().survivors),
                c.stages.back().expected,
                c.fit ? std::to_string(c.fit->slope).substr(0, 5).c_str() : "-",
                c.theory_dimension ? std::to_string(*c.theory_dimension).substr(0, 5).c_str() : "-");
  std::printf("outputs in %s:\n", fs::absolute(dir).lexically_normal().c_str());
  for (const auto& p : written) std::printf("  %s\n", p.filename().c_str());
  return 0;
}

int report(const CommonOptions& common) {
  const Session s = open_session(common);
  const CurdField field = run_engine(s, common.threads);
  std::fputs(format_report_table(make_report(s.recipe.design, s.seed, field, s.view)).c_str(),
             stdout);
  return 0;
}

int run(int argc, char** argv) {
  CLI::App app{"curdle: random curds (Mandelbrot curdling, overlaid after Cirovic 2014) "
               "for facade, paving, perforation and park layouts"};
  app.require_subcommand(1);

  CommonOptions gen_options, report_options;
  std::string out_dir;
  std::vector<std::string> outputs;
  CLI::App* gen = app.add_subcommand("generate", "Curdle a recipe and write its outputs");
  add_common_options(*gen, gen_options);
  gen->add_option("--out", out_dir, "Output directory (default: curdle-out/<recipe name>)");
  gen->add_option("--outputs", outputs, "Which outputs: report.json, cells.csv, preview.png")
      ->delimiter(',');
  CLI::App* rep = app.add_subcommand("report", "Print the per-stage report of a recipe");
  add_common_options(*rep, report_options);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  if (gen->parsed()) return generate(gen_options, out_dir, outputs);
  return report(report_options);
}

}  // namespace
}  // namespace curdle::cli

int main(int argc, char** argv) {
  try {
    return curdle::cli::run(argc, argv);
  } catch (const curdle::InputError& e) {
    std::fprintf(stderr, "curdle: error: %s\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "curdle: internal error: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "curdle: internal error: %s\n", e.what());
    return 1;
  }
}
