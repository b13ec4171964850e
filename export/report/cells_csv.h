// cells.csv: one row per finest cell of the view, RFC 4180, header
//   x[,y[,z]],value,<one 0/1 column per curd, named after it>
// coordinates in cells from the lattice origin. Streamed row by row.
#pragma once

#include <functional>
#include <ostream>

#include "curdle/curd.h"

namespace curdle {

void write_cells_csv(std::ostream& out, const Design& design, const CurdField& field,
                     const Box& view, const std::function<void(double)>& progress = {});

}  // namespace curdle
