#include "layout/merge_runs.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace curdle {

std::vector<GridRect> merge_runs(const std::vector<int>& grid, int64_t rows, int64_t columns,
                                 bool across_rows) {
  std::vector<GridRect> done;
  std::map<std::pair<int64_t, int64_t>, GridRect> open;  // by (column0, column1)
  for (int64_t r = 0; r < rows; ++r) {
    std::map<std::pair<int64_t, int64_t>, GridRect> next;
    for (int64_t c = 0; c < columns;) {
      const int v = grid[r * columns + c];
      int64_t end = c;
      while (end + 1 < columns && grid[r * columns + end + 1] == v) ++end;
      if (v >= 0) {
        auto it = open.find({c, end});
        if (across_rows && it != open.end() && it->second.value == v) {
          GridRect g = it->second;
          g.row1 = r;
          next[{c, end}] = g;
          open.erase(it);
        } else {
          next[{c, end}] = GridRect{r, c, r, end, v};
        }
      }
      c = end + 1;
    }
    for (auto& [key, g] : open) done.push_back(g);
    open = std::move(next);
  }
  for (auto& [key, g] : open) done.push_back(g);
  std::sort(done.begin(), done.end(), [](const GridRect& a, const GridRect& b) {
    return std::tie(a.value, a.row0, a.column0) < std::tie(b.value, b.row0, b.column0);
  });
  return done;
}

}  // namespace curdle
