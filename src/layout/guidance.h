// Advice on the lattice a surface is laid from: a first-stage cell larger than a third of the
// surface's shorter side means one that dies leaves a blank with straight edges across much of
// the surface (a base-4 curd on a small floor can lose a whole quadrant).
#pragma once

#include "curdle/curd.h"
#include "curdle/lattice.h"
#include "layout/layout.h"

namespace curdle {

// A note on layout.notes when a cell of the design's lattice at the first stage where one can
// die (b^(K-k) elements a side; the first stage unless every curd keeps p = 1 there) is larger
// than a third of the surface's shorter side, naming the bases and stage counts whose
// first-stage cells fit.
void advise_lattice(Layout& layout, const Design& design);

}  // namespace curdle
