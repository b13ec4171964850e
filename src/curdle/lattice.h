// The curdling lattice: base b, dimension E, K stages, and how survivors are chosen.
// Mandelbrot, The Fractal Geometry of Nature (1982), ch. 23 "random curds".
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace curdle {

enum class Mode {
  canonical,  // each subcell of a survivor survives independently with p_k (Mandelbrot)
  exact,      // each survivor keeps exactly p_k * b^E of its subcells, chosen at random
  quota,      // exactly round(p_k * candidates) of all the field's candidates survive
};

std::string_view to_string(Mode mode);

struct Lattice {
  int base = 4;
  int dimension = 2;
  int stages = 2;
  Mode mode = Mode::canonical;

  uint64_t children() const;                 // b^E subcells per cell
  uint64_t root_side() const;                // b^K finest cells a side of one root cell
  uint64_t cells_per_root(int stage) const;  // b^(E k)
  uint64_t side_in_cells(int stage) const;   // side of a stage-k cell in finest cells: b^(K-k)
  // E K log2 b, the bits of a cell's path within its root. Every count of a root's cells fits
  // in 64-bit arithmetic while it is at most kMaxPathBits: lattices above it are refused.
  double path_bits() const;
};

inline constexpr int kMaxPathBits = 62;

}  // namespace curdle
