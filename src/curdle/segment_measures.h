// Measures of rectangular segments of one generated view, read from its grid of values: what
// the seed search scores and what the page shows for a selection. Segments are boxes of
// absolute cells inside the view (1-D views are one row high).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "curdle/curd.h"

namespace curdle {

class SegmentMeasures {
 public:
  // `values` are the view's cells, row-major (values_in). Keeps its buffers between calls.
  void reset(const Design& design, const Box& view, std::vector<uint16_t> values);

  // Cells of `value` in the segment.
  uint64_t value_count(uint32_t value, const Box& segment);
  // Cells where `curd` survived (whatever the others did).
  uint64_t curd_count(size_t curd, const Box& segment);
  // counts[j], j = 0..K: lattice-aligned stage-j boxes meeting the segment that hold a
  // survivor of `curd` inside it; the same counts the report gives for a window.
  std::vector<uint64_t> box_counts(size_t curd, const Box& segment);
  // The largest 4-connected patch of cells of `value`, in cells.
  uint64_t largest_cluster(uint32_t value, const Box& segment);
  // The longest straight run (along x or y) of cells of `value`.
  uint64_t longest_run(uint32_t value, const Box& segment);
  // Gliding-box lacunarity of the cells of `value` with boxes of side `box` cells:
  // E[M^2] / E[M]^2 over every box position in the segment (Allain & Cloitre 1991);
  // 1 for an even spread, larger for clumps and gaps; nullopt when no cell has the value.
  std::optional<double> lacunarity(uint32_t value, const Box& segment, int64_t box);

  const std::vector<uint16_t>& values() const { return values_; }

 private:
  // Prefix sums of the indicator of `selector` (a value, or 2^n + curd), built on first use.
  const std::vector<uint32_t>& prefix(uint32_t selector);
  uint64_t sum(const std::vector<uint32_t>& prefix, const Box& segment) const;

  int base_ = 2, stages_ = 0, dimension_ = 2, curds_ = 0;
  Box view_;
  int64_t width_ = 0, height_ = 0;
  std::vector<uint16_t> values_;
  std::vector<std::vector<uint32_t>> prefix_;
  std::vector<bool> prefix_ready_;
  std::vector<uint32_t> seen_;  // cluster search: stamp per cell
  uint32_t stamp_ = 0;
  std::vector<uint32_t> queue_;
};

}  // namespace curdle
