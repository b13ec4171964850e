// Where each cell lives in the curd bitsets.
//
// The lattice is tiled by root cells (b^K finest cells a side); root (rx, ry, rz) is absolute,
// so a cell's identity never depends on the field or window it is seen through. The bitsets
// cover the grid of roots that meets the generated box, and a stage-k cell's bit is
//     root_local * b^(E k) + path,
// where path is the cell's ancestry read as base-b^E digits (stage 1 most significant) and the
// digit of a stage is sum_d (coordinate digit along axis d) * b^d. So the b^E children of a
// cell are b^E consecutive bits: generation writes whole words, box counting reads them.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "curdle/box.h"
#include "curdle/lattice.h"

namespace curdle {

using Coord = std::array<int64_t, 3>;

class CellIndex {
 public:
  CellIndex() = default;
  CellIndex(const Lattice& lattice, const Box& covered);

  // Bytes the index tables of a lattice take, known without building them (for memory
  // estimates; a deep lattice's tables alone can be gigabytes).
  static uint64_t table_bytes(const Lattice& lattice);

  const Lattice& lattice() const { return lattice_; }
  uint64_t roots() const { return roots_; }
  const Coord& root_origin() const { return root_origin_; }
  const Coord& root_count() const { return root_count_; }
  // The box of finest cells the root grid covers.
  Box covered_cells() const;

  Coord root_coords(uint64_t root_local) const;
  // The root's identity in the random stream (see random_stream.h).
  uint32_t root_code(uint64_t root_local) const;

  // Bit index of the finest cell at absolute coordinates c (must be inside covered_cells()).
  uint64_t finest_index(const Coord& c) const;
  // Index contributions for row-major scans: finest_index = root_base + axis_offset(d, c_d)...
  uint64_t root_base(const Coord& root) const;  // root in absolute root coordinates
  uint64_t axis_offset(int axis, uint64_t in_root) const {
    return hi_[axis][in_root / lo_span_] + lo_[axis][in_root % lo_span_];
  }

  // The digit of child t of a cell along each axis (t = sum_d digit_d b^d).
  const std::vector<std::array<uint8_t, 3>>& child_digits() const { return child_digits_; }

  // Absolute coordinates, in units of stage-k cells, of the stage-k cell with this bit index.
  Coord decode(int stage, uint64_t index) const;

 private:
  Lattice lattice_;
  Coord root_origin_{0, 0, 0};
  Coord root_count_{1, 1, 1};
  uint64_t roots_ = 0;
  std::vector<std::array<uint8_t, 3>> child_digits_;
  // axis_offset tables, split into the low and high stages so each stays ~sqrt(b^K) long.
  std::array<std::vector<uint64_t>, 3> lo_, hi_;
  uint64_t lo_span_ = 1;  // b^(low stages)
};

}  // namespace curdle
