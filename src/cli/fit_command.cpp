#include "cli/fit_command.h"

#include <cstdio>

#include "app/fit_run.h"
#include "app/run.h"
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
  if (!o.max_memory.empty()) request.max_memory = app::parse_bytes(o.max_memory, "max_memory");
  const app::FittedRecipe f = app::run_fit(request);
  const std::string written = app::write_fitted_recipe(f, o.out);

  std::string size;
  for (int d = 0; d < f.lattice.dimension; ++d)
    size += (d ? " x " : "") + std::to_string(f.size[static_cast<size_t>(d)]);
  std::printf("%s: %s cells, base %d, %d-D, %d stages\n", o.source.c_str(), size.c_str(),
              f.lattice.base, f.lattice.dimension, f.lattice.stages);
  for (const app::FittedCurd& c : f.curds) {
    std::printf("curd '%s'%s\n", c.name.c_str(),
                c.colour.empty() ? "" : (" (" + c.colour + ")").c_str());
    std::printf("  %5s %12s %12s %10s %21s\n", "stage", "measured", "expected", "p",
                "95 % interval of p");
    for (const StageFit& s : c.stages)
      std::printf("  %5d %12llu %12.1f %10.4f       %.4f to %.4f\n", s.stage,
                  static_cast<unsigned long long>(s.measured), s.expected, s.probability,
                  std::max(0.0, s.probability - 1.96 * s.sd),
                  std::min(1.0, s.probability + 1.96 * s.sd));
  }
  std::printf("recipe in %s\n", written.c_str());
  return 0;
}

}  // namespace curdle::cli
