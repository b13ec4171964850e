// `measure`: a picture quantised to values and measured (curdle/measure.h), its files written
// through a sink. Shared by the command line (and any shell that measures a picture).
#pragma once

#include <optional>
#include <string>

#include "app/output_sink.h"
#include "export/report/measure_files.h"

namespace curdle::app {

struct MeasureRequest {
  std::string image;                // a PNG, JPEG, TIFF or BMP picture
  int values = 2;                   // quantise to this many values, 2 to 16
  std::optional<double> threshold;  // or two values: darker than this (0 to 1) is value 1
  int base = 2;                     // boxes of side base^j
  uint64_t max_memory = 0;          // bytes; 0: default_memory_limit()
};

// A picture a user names, read as hostile input (bounded_image.h): at most 8192 x 8192 pixels
// and `max_memory` bytes (0: default_memory_limit()). Measure and fit read pictures this way.
LuminanceImage read_picture(const std::string& path, uint64_t max_memory);
// The box base given on the command line, 2 to 64; InputError otherwise.
void check_base(int base);

// InputError for values, threshold or base out of range (checked before any reading).
void check_measure_options(const MeasureRequest& request);

// Reads, quantises and measures the picture; InputError for bad options or pictures.
MeasuredPicture run_measure(const MeasureRequest& request);
// The same for a picture already read (request.image is only its name); `source` names it in
// measure.json.
MeasuredPicture measure_picture(const LuminanceImage& image, const std::string& source,
                                const MeasureRequest& request);

bool is_measure_output_name(const std::string& name, bool folder);
// measure.json and measure.png.
void write_measure_outputs(const MeasuredPicture& picture, OutputSink& sink);

}  // namespace curdle::app
