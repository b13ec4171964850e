#include "cli/measure_command.h"

#include <cstdio>
#include <filesystem>

#include "app/measure_run.h"
#include "app/run.h"
#include "cli/chain_table.h"
#include "cli/options.h"

namespace fs = std::filesystem;

namespace curdle::cli {

void add_measure_options(CLI::App& c, MeasureOptions& o) {
  c.add_option("image", o.image, "Picture to measure (PNG, TIFF, JPEG, ...)")
      ->required()
      ->check(kNotEmpty);
  auto* values = c.add_option("--values", o.values,
                              "Quantise the picture to this many values, 2 to 16, lightest "
                              "first (default 2)");
  c.add_option("--threshold", o.threshold,
               "Two values instead: darker than this luminance (0 black to 1 white) is value 1")
      ->excludes(values);
  c.add_option("--base", o.base, "Boxes of side base^j pixels (default 2; 3 for a carpet)");
  c.add_option("--stages", o.stages,
               "Also read the values as one Markov curd of values - 1 states, K stages of this "
               "base: its states and boxes per stage beside the fitted chain's, and whether the "
               "cells read better as overlaid curds");
  c.add_option("--out", o.out_dir, "Output directory (default: curdle-out/<image name>-measure)")
      ->check(kNotEmpty);
  c.add_option("--max-memory", o.max_memory, "Refuse pictures above this much memory, e.g. 2G")
      ->check(kNotEmpty);
}

int run_measure(const MeasureOptions& o) {
  app::MeasureRequest request;
  request.image = o.image;
  request.values = o.values;
  request.threshold = o.threshold;
  request.base = o.base;
  request.stages = o.stages;
  if (!o.max_memory.empty()) request.max_memory = app::parse_bytes(o.max_memory, "max_memory");
  std::optional<app::ChainReading> chain;
  const MeasuredPicture picture = app::run_measure(request, &chain);
  const fs::path dir =
      o.out_dir.empty() ? fs::path("curdle-out") / (fs::path(o.image).stem().string() + "-measure")
                        : fs::path(o.out_dir);
  app::StagingDirectory sink(dir, app::is_measure_output_name);
  app::write_measure_outputs(picture, sink, chain ? &*chain : nullptr);
  sink.commit();

  const Measurement& m = picture.measurement;
  std::printf("%s: %lld x %lld pixels, %zu values, boxes of side %d^j, lacunarity box %lld\n",
              picture.source.c_str(), static_cast<long long>(m.width),
              static_cast<long long>(m.height), m.values.size(), m.base,
              static_cast<long long>(m.lacunarity_box));
  std::printf("%6s %8s %12s %8s %11s %10s %6s %7s\n", "value", "colour", "pixels", "share",
              "lacunarity", "dimension", "R^2", "levels");
  for (const ValueMeasure& v : m.values) {
    const std::string colour = level_colour(picture.levels.at(v.value));
    std::printf("%6u %8s %12llu %8.4f %11s", v.value, colour.c_str(),
                static_cast<unsigned long long>(v.count), v.share,
                v.lacunarity ? std::to_string(*v.lacunarity).substr(0, 8).c_str() : "-");
    if (v.fit)
      std::printf(" %10.4f %6.4f %7d\n", v.fit->slope, v.fit->r2, v.fit->points);
    else
      std::printf(" %10s %6s %7s\n", v.most_common ? "(ground)" : "-", "-", "-");
  }
  if (chain) print_chain(*chain), print_levels(*chain), print_readings(*chain);
  std::printf("outputs in %s: measure.json, measure.png\n",
              fs::absolute(dir).lexically_normal().c_str());
  return 0;
}

}  // namespace curdle::cli
