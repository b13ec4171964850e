// Box counting with boxes aligned to the lattice (side b^-j, origin at the lattice corner):
// the count at level j is exactly the number of stage-j cells that keep at least one final
// survivor, so it is read off the stage bitsets without touching coordinates.
// Box-counting dimension: Falconer, Fractal Geometry (2003), sec. 3.1; fitted by least squares
// of log N_j against j log b.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "curdle/curd.h"

namespace curdle {

// counts[j], j = 0..K: cells of stage j (of the root grid) with a surviving finest descendant.
// `scratch` keeps its allocations between calls.
std::vector<uint64_t> box_counts(const Curd& curd, uint64_t children, std::vector<Bitset>& scratch);
std::vector<uint64_t> box_counts(const Curd& curd, uint64_t children);
// The same into `counts`, reusing its allocation (searches over many seeds).
void box_counts_into(const Curd& curd, uint64_t children, std::vector<Bitset>& scratch,
                     std::vector<uint64_t>& counts);

// Survivors of one stage; on a sparse stage only the words under coarser survivors are read.
uint64_t count_survivors(const Curd& curd, int stage, uint64_t children);

struct LineFit {
  double slope = 0;
  double r2 = 0;
  int points = 0;
};

// Least-squares slope of log counts[j] against j log b over the levels with a non-zero count;
// nullopt with fewer than two such levels.
std::optional<LineFit> fit_box_dimension(const std::vector<uint64_t>& counts, int base);
// The same over expected (real) counts.
std::optional<LineFit> fit_box_dimension(const std::vector<double>& counts, int base);

}  // namespace curdle
