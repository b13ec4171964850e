// A view's cells found row by row: the same finest index as the cell index gives each cell,
// over views that start left of and below the origin and run over several roots, in one, two
// and three dimensions.
#include "curdle/view_cells.h"

#include <gtest/gtest.h>

#include "curdle/curdling.h"
#include "test_support.h"

namespace curdle {
namespace {

TEST(ViewCells, EachCellIsWhereTheCellIndexPutsIt) {
  for (const int dimension : {1, 2, 3}) {
    const Design d = test::design(3, dimension, {{"1/2", "1/2"}});
    Box view = d.field;
    view.origin = {-7, dimension >= 2 ? -4 : 0, dimension == 3 ? -2 : 0};
    view.size = {23, dimension >= 2 ? 19 : 1, dimension == 3 ? 13 : 1};
    const CurdField field = curdle(d, 5, view);
    const ViewCells cells(field, view);
    size_t wrong = 0;
    for (int64_t z = 0; z < view.size[2]; ++z)
      for (int64_t y = 0; y < view.size[1]; ++y)
        for (int64_t x = 0; x < view.size[0]; ++x) {
          const Coord c{view.origin[0] + x, view.origin[1] + y, view.origin[2] + z};
          wrong += cells.at(cells.row(y, z), x) != field.index.finest_index(c);
        }
    EXPECT_EQ(wrong, 0u) << "E = " << dimension;
  }
}

}  // namespace
}  // namespace curdle
