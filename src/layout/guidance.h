// Advice on the lattice a surface is laid from: a first-stage cell larger than a third of the
// surface's shorter side means one that dies leaves a blank with straight edges across much of
// the surface (a base-4 curd on a small floor can lose a whole quadrant).
#pragma once

#include "curdle/lattice.h"
#include "layout/layout.h"

namespace curdle {

// A note on layout.notes when a first-stage cell of `lattice` (b^(K-1) elements a side) is
// larger than a third of the surface's shorter side, naming the bases and stage counts whose
// first-stage cells fit.
void advise_lattice(Layout& layout, const Lattice& lattice);

}  // namespace curdle
