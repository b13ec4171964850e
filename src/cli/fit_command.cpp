#include "cli/fit_command.h"

#include <fmt/format.h>

#include <cstdio>

#include "app/fit_run.h"
#include "app/run.h"
#include "cli/chain_table.h"
#include "cli/options.h"

namespace curdle::cli {

void add_fit_options(CLI::App& c, FitOptions& o) {
  c.add_option("source", o.source,
               "Picture to fit (PNG, TIFF, JPEG, ...), or a cells.csv as generate writes it")
      ->required()
      ->check(kNotEmpty);
  c.add_option("--base", o.base, "Lattice base b (default 2)");
  c.add_option("--stages", o.stages, "Stages K")->required();
  c.add_option("--curds", o.curds,
               "Curds n: the picture is quantised to 2^n values, lightest first, whose bits are "
               "the curds (default 1: the dark figure); a cells.csv brings its own curds");
  c.add_option("--states", o.states,
               "Fit one Markov curd of S living states instead: the picture is quantised to S + 1 "
               "tones, the lightest the ground (dead); a cells.csv's values are its states. Both "
               "readings are compared and the supported one named");
  c.add_flag("--stage-wise", o.stage_wise,
             "Fit the chain's matrix per stage (default: one matrix)");
  c.add_flag("--wheys", o.wheys,
             "Fit the chain's dead row too: dead cells may come back (default: dead stays dead)");
  c.add_option("--cell-pixels", o.cell_pixels,
               "Pixels a side of a cell of the picture (default: found, e.g. a preview's 16 x 16 "
               "pixel cells; 1: a pixel a cell)");
  c.add_option("--out", o.out, "Recipe to write (default: curdle-out/<source name>-fit.toml)")
      ->check(kNotEmpty);
  c.add_option("--max-memory", o.max_memory, "Refuse pictures above this much memory, e.g. 2G")
      ->check(kNotEmpty);
}

int run_fit(const FitOptions& o) {
  app::FitRequest request;
  request.source = o.source;
  request.base = o.base;
  request.stages = o.stages;
  request.curds = o.curds;
  request.cell_pixels = o.cell_pixels;
  request.states = o.states;
  request.stage_wise = o.stage_wise;
  request.wheys = o.wheys;
  if (!o.max_memory.empty()) request.max_memory = app::parse_bytes(o.max_memory, "max_memory");
  const app::FittedRecipe f = app::run_fit(request);
  const std::string written = app::write_fitted_recipe(f, o.out);

  std::string size;
  for (int d = 0; d < f.lattice.dimension; ++d)
    size += (d ? " x " : "") + std::to_string(f.size[static_cast<size_t>(d)]);
  std::printf("%s: %s cells, base %d, %d-D, %d stages\n", o.source.c_str(), size.c_str(),
              f.lattice.base, f.lattice.dimension, f.lattice.stages);
  if (f.pixels_per_cell > 1)
    std::printf("cells of %d x %d pixels (a preview's): fitted in cells\n", f.pixels_per_cell,
                f.pixels_per_cell);
  if (f.by_colour) std::printf("curds told apart by the picture's colours\n");
  if (f.recipe_is_chain) print_chain(*f.chain), print_levels(*f.chain);
  for (const app::FittedCurd& c : f.curds) {
    std::printf("curd '%s'%s\n", c.name.c_str(),
                c.colour.empty() ? "" : (" (" + c.colour + ")").c_str());
    std::printf("  %5s %10s %20s %7s %8s %17s %10s\n", "stage", "measured", "expected (sd)", "z",
                "p", "95 % interval", "branching");
    for (const StageFit& s : c.fit.stages) {
      const std::string expected = fmt::format("{:.1f} ({:.1f})", s.expected, s.expected_sd);
      const std::string test =
          s.degrees ? fmt::format("p = {:.2g}", s.p_value) : std::string("too few");
      std::printf("  %5d %10llu %20s %7.2f %8.4f  %.4f to %.4f %10s\n", s.stage,
                  static_cast<unsigned long long>(s.measured), expected.c_str(), s.z, s.probability,
                  s.low, s.high, test.c_str());
    }
    if (c.fit.degrees)
      std::printf(
          "  branching against the fitted curd: chi-square %.1f on %d degrees of freedom, "
          "p = %.2g\n",
          c.fit.chi_square, c.fit.degrees, c.fit.p_value);
  }
  if (!f.curds.empty())
    std::printf(
        "The fit makes each stage's count, given the stage before, what the curd expects; "
        "'expected' is the count from the occupied roots, z how far the picture is from it.\n");
  if (f.chain) print_readings(*f.chain);
  for (const std::string& w : f.warnings) std::printf("warning: %s\n", w.c_str());
  std::printf("recipe in %s\n", written.c_str());
  return 0;
}

}  // namespace curdle::cli
