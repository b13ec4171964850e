#include "curdle/cell_index.h"

#include <cassert>
#include <cmath>

namespace curdle {
namespace {

// Path contribution of an in-root coordinate along one axis, for the digits of stages
// [first, last] (1-based, stage 1 most significant).
uint64_t axis_path(const Lattice& l, int axis, uint64_t c, int first, int last) {
  const uint64_t b = l.base;
  uint64_t axis_weight = 1;
  for (int d = 0; d < axis; ++d) axis_weight *= b;
  uint64_t sum = 0;
  for (int stage = l.stages; stage >= 1; --stage) {  // least significant digit first
    const uint64_t digit = c % b;
    c /= b;
    if (stage >= first && stage <= last)
      sum += digit * axis_weight * l.cells_per_root(l.stages - stage);
  }
  return sum;
}

}  // namespace

uint64_t CellIndex::table_bytes(const Lattice& lattice) {
  const int low_stages = lattice.stages / 2;
  const double spans = std::pow(static_cast<double>(lattice.base), low_stages) +
                       std::pow(static_cast<double>(lattice.base), lattice.stages - low_stages);
  const double bytes = spans * sizeof(uint64_t) * lattice.dimension +
                       std::pow(static_cast<double>(lattice.base), lattice.dimension) * 3;
  return bytes >= 1.8e19 ? UINT64_MAX : static_cast<uint64_t>(bytes);
}

CellIndex::CellIndex(const Lattice& lattice, const Box& covered) : lattice_(lattice) {
  const int64_t side = static_cast<int64_t>(lattice.root_side());
  roots_ = 1;
  for (int d = 0; d < 3; ++d) {
    if (d < lattice.dimension) {
      root_origin_[d] = floor_div(covered.origin[d], side);
      const int64_t last = floor_div(covered.origin[d] + covered.size[d] - 1, side);
      root_count_[d] = last - root_origin_[d] + 1;
    } else {
      root_origin_[d] = 0;
      root_count_[d] = 1;
    }
    roots_ *= static_cast<uint64_t>(root_count_[d]);
  }
  const int low_stages = lattice.stages / 2;
  const int high_stages = lattice.stages - low_stages;
  lo_span_ = 1;
  for (int i = 0; i < low_stages; ++i) lo_span_ *= lattice.base;
  uint64_t hi_span = 1;
  for (int i = 0; i < high_stages; ++i) hi_span *= lattice.base;
  for (int d = 0; d < lattice.dimension; ++d) {
    lo_[d].resize(lo_span_);
    hi_[d].resize(hi_span);
    for (uint64_t c = 0; c < lo_span_; ++c)
      lo_[d][c] = axis_path(lattice, d, c, high_stages + 1, lattice.stages);
    for (uint64_t c = 0; c < hi_span; ++c)
      hi_[d][c] = axis_path(lattice, d, c * lo_span_, 1, high_stages);
  }
  for (int d = lattice.dimension; d < 3; ++d) {
    lo_[d].assign(1, 0);
    hi_[d].assign(1, 0);
  }
  child_digits_.assign(lattice.children(), {0, 0, 0});
  for (uint64_t t = 0; t < child_digits_.size(); ++t) {
    uint64_t rest = t;
    for (int d = 0; d < lattice.dimension; ++d) {
      child_digits_[t][d] = static_cast<uint8_t>(rest % lattice.base);
      rest /= lattice.base;
    }
  }
}

Box CellIndex::covered_cells() const {
  Box box;
  const int64_t side = static_cast<int64_t>(lattice_.root_side());
  for (int d = 0; d < lattice_.dimension; ++d) {
    box.origin[d] = root_origin_[d] * side;
    box.size[d] = root_count_[d] * side;
  }
  return box;
}

Coord CellIndex::root_coords(uint64_t local) const {
  Coord r;
  for (int d = 0; d < 3; ++d) {
    r[d] = root_origin_[d] + static_cast<int64_t>(local % root_count_[d]);
    local /= root_count_[d];
  }
  return r;
}

uint32_t CellIndex::root_code(uint64_t local) const {
  const Coord r = root_coords(local);
  switch (lattice_.dimension) {
    case 1:
      return static_cast<uint32_t>(r[0]);
    case 2:
      return static_cast<uint32_t>(r[0]) | static_cast<uint32_t>(r[1]) << 16;
    default:
      return static_cast<uint32_t>(r[0]) | static_cast<uint32_t>(r[1]) << 10 |
             static_cast<uint32_t>(r[2]) << 20;
  }
}

uint64_t CellIndex::root_base(const Coord& root) const {
  uint64_t local = 0;
  for (int d = 2; d >= 0; --d)
    local = local * root_count_[d] + static_cast<uint64_t>(root[d] - root_origin_[d]);
  return local * lattice_.cells_per_root(lattice_.stages);
}

uint64_t CellIndex::finest_index(const Coord& c) const {
  const int64_t side = static_cast<int64_t>(lattice_.root_side());
  Coord root{0, 0, 0};
  uint64_t index = 0;
  for (int d = 0; d < lattice_.dimension; ++d) {
    root[d] = floor_div(c[d], side);
    index += axis_offset(d, static_cast<uint64_t>(c[d] - root[d] * side));
  }
  return root_base(root) + index;
}

Coord CellIndex::decode(int stage, uint64_t index) const {
  const uint64_t per_root = lattice_.cells_per_root(stage);
  const uint64_t b = lattice_.base, B = lattice_.children();
  const Coord root = root_coords(index / per_root);
  uint64_t path = index % per_root;
  Coord c{0, 0, 0};
  uint64_t weight = 1;  // b^(stage - level)
  for (int level = stage; level >= 1; --level) {
    uint64_t digit = path % B;
    path /= B;
    for (int d = 0; d < lattice_.dimension; ++d) {
      c[d] += static_cast<int64_t>((digit % b) * weight);
      digit /= b;
    }
    weight *= b;
  }
  // weight is now b^stage: the stage-k cells a root spans.
  for (int d = 0; d < lattice_.dimension; ++d) c[d] += root[d] * static_cast<int64_t>(weight);
  return c;
}

}  // namespace curdle
