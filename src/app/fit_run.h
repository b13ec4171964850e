// `fit`: a recipe fitted to a picture or a cells.csv (curdle/fit.h). A picture is quantised to
// 2^n values whose bits are the curds (value 0 the lightest); a cells.csv brings its own curds
// and dimension. Each curd's per-stage probabilities are fitted to its occupied cells, and the
// recipe is written as TOML that curdle reads back.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "app/chain_reading.h"
#include "curdle/fit.h"
#include "curdle/lattice.h"
#include "io/image.h"

namespace curdle::app {

struct FitRequest {
  std::string source;  // a PNG, JPEG, TIFF or BMP picture, or a cells.csv
  int base = 2;
  int stages = 0;
  int curds = 1;
  int cell_pixels = 0;      // a picture's cells are this many pixels a side; 0: found from it
  uint64_t max_memory = 0;  // bytes; 0: default_memory_limit()
  // A Markov curd of this many living states instead of overlaid curds (0: curds): a picture's
  // S + 1 tones, the lightest the ground; a cells.csv's values. A cells.csv of one Markov curd
  // is fitted as a chain of its own states whatever this says.
  int states = 0;
  bool stage_wise = false;  // the chain's matrix fitted per stage, not one for all
  bool wheys = false;       // the chain's dead row fitted too (dead cells that come back)
};

struct FittedCurd {
  std::string name;
  std::string colour;  // "#rrggbb": the grey of the value holding only this curd; empty: none
  CurdFit fit;         // per stage: probability, interval, counts and the test
};

struct FittedRecipe {
  std::string name;  // of the source, for the recipe
  Lattice lattice;
  std::array<int64_t, 3> size{1, 1, 1};  // the field in cells
  int pixels_per_cell = 1;               // a picture's cells, in pixels a side
  bool by_colour = false;                // its curds told apart by its colours
  std::vector<FittedCurd> curds;
  // The cells read as one Markov curd: the recipe's curd when recipe_is_chain, else beside the
  // overlaid curds, to say which reading the cells support.
  std::optional<ChainReading> chain;
  bool recipe_is_chain = false;
  std::string toml;  // the recipe, checked by reading it back
  // What the fit cannot vouch for: a curd no curd at these stages explains (naming the stages
  // that fail and which way), or too few cells to tell. Also written into the recipe's text.
  std::vector<std::string> warnings;
};

// A fitted probability as the recipe writes it ("0.6124").
std::string probability_text(double probability);

// InputError for a base, stage count or curd count out of range (checked before any reading).
void check_fit_options(const FitRequest& request);
// InputError (naming `stages`) for a lattice whose b^(E K) cells to a root pass kMaxPathBits.
void check_fit_lattice(const Lattice& lattice);

FittedRecipe run_fit(const FitRequest& request);

// Writes the fitted recipe to `out` (empty: curdle-out/<name>.toml), whole or not at all, making
// its folder; returns where it went.
std::string write_fitted_recipe(const FittedRecipe& fitted, const std::string& out);
// A picture already read (request.source is only its name, for the recipe's name and note).
FittedRecipe fit_picture(const LuminanceImage& image, const FitRequest& request);

}  // namespace curdle::app
