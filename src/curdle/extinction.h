// What box counting should give at a finite number of stages. A stage-k cell that survives
// still shows in the box count at level k only if some finest descendant inside the view
// survives all later stages; sub-curds die out (extinction), so the expected count is below
// C_k P_k. With e_k the chance that a surviving stage-k cell leaves no finest survivor in the
// view, the generating function of its children gives (canonical mode, B = b^E children, the
// ones outside the view never counting):
//   e_K = 0,   e_k = prod over children in the view of (1 - p_(k+1) (1 - e_(k+1)(child)))
// and in exact mode, where exactly m = p_(k+1) B children survive, chosen without replacement,
// e_k = E[prod over the chosen children in the view of e_(k+1)(child)] (hypergeometric).
// A cell cut by the view differs from a whole one only in which children lie inside, so the
// cells of a level fall into at most 3^E classes along the view's edges: exact at any crop.
// Quota mode is taken as canonical (the field-wide quota differs by rounding only), and so are
// exact mode's cells cut by the view when a cell has over 512 children (off by O(1/B)).
// Expected box count at level k: sum over the stage-k cells meeting the view of
// P_k (1 - e_k(cell)).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "curdle/box.h"
#include "curdle/cell_shapes.h"
#include "curdle/lattice.h"
#include "curdle/probability.h"

namespace curdle {

// Levels 0..K: the expected number of stage-k cells meeting `view` that keep a final survivor
// in it.
std::vector<double> expected_box_counts(const Lattice& lattice, const std::vector<Probability>& p,
                                        const Box& view);
// The same with each box weighted by the share of its cells inside the view: a box the view
// cuts counts for what it shows (share_weighted_box_counts).
std::vector<double> expected_share_weighted_box_counts(const Lattice& lattice,
                                                       const std::vector<Probability>& p,
                                                       const Box& view);

// e_k above for a surviving stage-k cell whose inside part is `shape`: the chance it leaves no
// finest survivor inside the view, with p_(k+1)..p_K. Remembers what it worked out, so that
// the cells of a stage (a few classes along the view's edges) cost one recursion.
class ExtinctionChance {
 public:
  ExtinctionChance(const Lattice& lattice, std::vector<Probability> p);
  double operator()(int stage, const CellShape& shape);

 private:
  Lattice l_;
  std::vector<Probability> p_;
  std::map<std::pair<int, CellShape>, double> memo_;
};

// Measured share-weighted box counts, levels 0..K, of a curd given as its finest cells over
// `view` (x fastest, then y, then z; cells in lattice coordinates from view.origin).
std::vector<double> share_weighted_box_counts(const Lattice& lattice, const Box& view,
                                              const std::vector<bool>& cells);

}  // namespace curdle
