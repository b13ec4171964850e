// `measure`: a picture quantised to values and measured (curdle/measure.h), its files written
// through a sink. Shared by the command line (and any shell that measures a picture).
#pragma once

#include <optional>
#include <string>

#include "app/chain_reading.h"
#include "app/output_sink.h"
#include "export/report/measure_files.h"

namespace curdle::app {

struct MeasureRequest {
  std::string image;                // a PNG, JPEG, TIFF or BMP picture
  int values = 2;                   // quantise to this many values, 2 to 16
  std::optional<double> threshold;  // or two values: darker than this (0 to 1) is value 1
  int base = 2;                     // boxes of side base^j
  uint64_t max_memory = 0;          // bytes; 0: default_memory_limit()
  // With K stages, the values read as one Markov curd of values - 1 living states on a lattice
  // of this base (chain_reading.h), its states and boxes per stage beside the fitted chain's.
  int stages = 0;
};

// A picture a user names, read as hostile input (bounded_image.h): at most 8192 x 8192 pixels
// and `max_memory` bytes (0: default_memory_limit()). Measure and fit read pictures this way.
LuminanceImage read_picture(const std::string& path, uint64_t max_memory);
// The box base given on the command line, 2 to 64; InputError otherwise.
void check_base(int base);

// InputError for values, threshold or base out of range (checked before any reading).
void check_measure_options(const MeasureRequest& request);

// Reads, quantises and measures the picture; InputError for bad options or pictures. With
// request.stages and `chain`, the values' chain too (measured_chain).
MeasuredPicture run_measure(const MeasureRequest& request,
                            std::optional<ChainReading>* chain = nullptr);
// The same for a picture already read (request.image is only its name); `source` names it in
// measure.json.
MeasuredPicture measure_picture(const LuminanceImage& image, const std::string& source,
                                const MeasureRequest& request);

// The picture's values fitted as one Markov curd (request.stages > 0): the chain with its
// intervals, its stages beside the picture's, and which reading the cells support.
ChainReading measured_chain(const LuminanceImage& image, const MeasureRequest& request);

bool is_measure_output_name(const std::string& name, bool folder);
// measure.json (with the chain, when given, as its "chain") and measure.png.
void write_measure_outputs(const MeasuredPicture& picture, OutputSink& sink,
                           const ChainReading* chain = nullptr);

}  // namespace curdle::app
