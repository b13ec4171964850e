// Curdling: Mandelbrot's cascade, stage by stage, for every curd of a design.
// B. Mandelbrot, The Fractal Geometry of Nature (1982), pp. 210-213 (canonical curdling);
// I. Ciric (Cirovic), "Random curds as mathematical models of fractal rhythm in
// architecture", SPATIUM 31 (2014) (stage-wise probabilities, overlaid curds).
//
// Only the children of survivors are visited, and only those that meet the generated box.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "curdle/curd.h"

namespace curdle {

struct GenerateOptions {
  uint64_t max_memory_bytes = 0;         // 0: no limit
  std::string memory_limit_hint;         // how the user raises the limit, for the message
  std::function<void(double)> progress;  // fraction of the work done, from 0 to 1
};

// The box the engine generates to show `view`: the view itself, except in quota mode, where
// survivors are counted over the whole field and so the whole field is generated.
Box generation_box(const Design& design, const Box& view);

// Quota mode's survivors at stage k: round(P_k * C_k), P_k = p_1 ... p_k, C_k the stage-k
// cells meeting the field, so every stage (and the final count) hits its expected count
// exactly. Rounding p_k * candidates stage by stage instead would drift (fig. 7 of the paper:
// 469 instead of 455 of 4096).
uint64_t quota_target(const std::vector<Probability>& p, int stage, uint64_t cells);

// Bytes the bitsets of all curds and stages take when generating `box`.
uint64_t estimate_memory(const Design& design, const Box& box);

// Generates the curds of `design` for `seed` seen through `view` (a box inside the field).
// Throws InputError when the estimate exceeds options.max_memory_bytes.
CurdField curdle(const Design& design, uint64_t seed, const Box& view,
                 const GenerateOptions& options = {});

// The same, reusing the allocations of `out` (for searches over many seeds).
void curdle_into(const Design& design, uint64_t seed, const Box& view, CurdField& out,
                 const GenerateOptions& options = {});

}  // namespace curdle
