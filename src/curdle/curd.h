// Curds as data: per curd and stage, one bit per cell of the root grid (see cell_index.h).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "curdle/bitset.h"
#include "curdle/box.h"
#include "curdle/cell_index.h"
#include "curdle/density.h"
#include "curdle/lattice.h"
#include "curdle/probability.h"

namespace curdle {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

struct MarkovChain;  // markov.h

struct CurdSpec {
  std::string name;
  // One per stage. A Markov curd's planes hold its living set's per-stage survival, for
  // guidance only: the chain is what draws and what the report's theory uses.
  std::vector<Probability> probabilities;
  std::optional<Rgb> colour;
  std::optional<DensityField> density;  // [curds.density]; canonical mode only (density.h)
  // A Markov curd's bit planes share its chain; `plane` is the bit of the state this one holds.
  std::shared_ptr<const MarkovChain> chain;
  int plane = 0;
};

// Everything the engine needs besides the seed: the recipe without its file.
struct Design {
  std::string name;
  std::string description;  // the recipe's, for title blocks
  Lattice lattice;
  std::vector<CurdSpec> curds;
  Box field;  // in finest cells, origin at the lattice origin
};

struct Curd {
  std::vector<Bitset> stages;  // stages[0] marks the roots, stages[K] the finest survivors
};

// The generated curds of one design and seed, over the roots that meet `generated`.
struct CurdField {
  CellIndex index;
  Box generated;      // cells outside it were never visited and read as dead
  uint64_t seed = 0;  // the stream it was drawn from
  std::vector<Curd> curds;

  const Bitset& finest(size_t curd) const { return curds[curd].stages.back(); }
  // The value of the cell at finest index i: bit c set when curd c survived there.
  uint32_t value_of(uint64_t i) const {
    uint32_t v = 0;
    for (size_t c = 0; c < curds.size(); ++c) v |= uint32_t{finest(c).test(i)} << c;
    return v;
  }
  uint32_t value_at(const Coord& cell) const { return value_of(index.finest_index(cell)); }
};

}  // namespace curdle
