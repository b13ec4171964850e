#include "curdle/lattice.h"

#include <cmath>

namespace curdle {
namespace {
uint64_t power(uint64_t b, int e) {
  uint64_t r = 1;
  for (int i = 0; i < e; ++i) r *= b;
  return r;
}
}  // namespace

std::string_view to_string(Mode mode) {
  switch (mode) {
    case Mode::canonical:
      return "canonical";
    case Mode::exact:
      return "exact";
    case Mode::quota:
      return "quota";
  }
  return "?";
}

uint64_t Lattice::children() const { return power(base, dimension); }
uint64_t Lattice::root_side() const { return power(base, stages); }
uint64_t Lattice::cells_per_root(int stage) const { return power(children(), stage); }
uint64_t Lattice::side_in_cells(int stage) const { return power(base, stages - stage); }

double Lattice::path_bits() const {
  return dimension * stages * std::log2(static_cast<double>(base));
}

}  // namespace curdle
