#include "app/measure_run.h"

#include <cmath>
#include <filesystem>

#include "app/fit_run.h"
#include "app/run.h"
#include "io/bounded_image.h"

namespace curdle::app {
namespace {
// 8192 x 8192: box counts and lacunarity take about 30 bytes a pixel.
constexpr int64_t kMaxSide = 8192;
constexpr uint64_t kMaxPixels = uint64_t{kMaxSide} * kMaxSide;
}  // namespace

LuminanceImage read_picture(const std::string& path, uint64_t max_memory) {
  return read_bounded_luminance(path, "the picture", SourceLocation{path, 0, 0, "", ""},
                                max_memory ? max_memory : default_memory_limit(), kMaxPixels, {},
                                kMaxSide);
}

void check_base(int base) {
  if (base < 2 || base > 64)
    throw InputError(parameter("base"), "must be from 2 to 64, not " + std::to_string(base));
}

void check_measure_options(const MeasureRequest& r) {
  if (r.values < 2 || r.values > 16)
    throw InputError(parameter("values"),
                     "must be from 2 to 16 (the values the picture is quantised to), not " +
                         std::to_string(r.values));
  if (r.threshold && !(*r.threshold > 0 && *r.threshold < 1))
    throw InputError(parameter("threshold"),
                     "must be a luminance between 0 (black) and 1 (white), e.g. 0.5");
  check_base(r.base);
  if (r.stages < 0 || r.stages > 30)
    throw InputError(parameter("stages"),
                     "must be from 1 to 30, or 0 for no chain, not " + std::to_string(r.stages));
}

MeasuredPicture run_measure(const MeasureRequest& r, std::optional<ChainReading>* chain) {
  check_measure_options(r);
  const LuminanceImage image = read_picture(r.image, r.max_memory);
  if (chain && r.stages > 0) *chain = measured_chain(image, r);
  return measure_picture(image, std::filesystem::path(r.image).filename().string(), r);
}

MeasuredPicture measure_picture(const LuminanceImage& image, const std::string& source,
                                const MeasureRequest& r) {
  check_measure_options(r);
  MeasuredPicture picture;
  picture.source = source;
  const int count = r.threshold ? 2 : r.values;
  ValueGrid grid;
  if (r.threshold) {
    grid = threshold(image.width, image.height, image.luminance, *r.threshold);
    double light = 0, dark = 0, nl = 0, nd = 0;
    for (size_t i = 0; i < image.luminance.size(); ++i)
      (grid.values[i] ? (dark += image.luminance[i], nd += 1)
                      : (light += image.luminance[i], nl += 1));
    picture.levels = {nl ? light / nl : 1.0, nd ? dark / nd : 0.0};
  } else {
    grid = quantise(image.width, image.height, image.luminance, count, picture.levels);
  }
  picture.measurement = measure(grid, count, r.base);
  return picture;
}

bool is_measure_output_name(const std::string& name, bool folder) {
  return !folder && (name == "measure.json" || name == "measure.png");
}

ChainReading measured_chain(const LuminanceImage& image, const MeasureRequest& r) {
  if (r.threshold)
    throw InputError(parameter("stages"),
                     "a chain is fitted to the values --values quantises to, not to a threshold's "
                     "two: give --values 3 or more with --stages");
  FitRequest fit;
  fit.source = r.image;
  fit.base = r.base;
  fit.stages = r.stages;
  fit.states = r.values - 1;
  return *fit_picture(image, fit).chain;
}

void write_measure_outputs(const MeasuredPicture& picture, OutputSink& sink,
                           const ChainReading* chain) {
  nlohmann::ordered_json j = measure_to_json(picture);
  if (chain) j["chain"] = chain_reading_json(*chain, static_cast<int>(chain->levels.size()) - 1);
  sink.write("measure.json", [&](std::ostream& out) { out << j.dump(1) << "\n"; });
  const std::string png = encode_png(plot_box_counts(picture));
  sink.write("measure.png", [&](std::ostream& out) { out << png; });
}

}  // namespace curdle::app
