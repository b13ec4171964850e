#include "curdle/boxcount.h"

#include <cmath>

namespace curdle {

std::vector<uint64_t> box_counts(const Curd& curd, uint64_t children,
                                 std::vector<Bitset>& scratch) {
  const int K = static_cast<int>(curd.stages.size()) - 1;
  std::vector<uint64_t> counts(K + 1, 0);
  counts[K] = curd.stages[K].count();
  scratch.resize(2);
  const Bitset* below = &curd.stages[K];
  for (int j = K - 1; j >= 0; --j) {
    Bitset& alive = scratch[j & 1];
    alive.assign_zero(curd.stages[j].size);
    uint64_t n = 0;
    // Only survivors of stage j can have surviving descendants.
    for_each_set(curd.stages[j], 0, curd.stages[j].size, [&](uint64_t i) {
      if (below->any_in(i * children, (i + 1) * children)) {
        alive.set(i);
        ++n;
      }
    });
    counts[j] = n;
    below = &alive;
  }
  return counts;
}

std::vector<uint64_t> box_counts(const Curd& curd, uint64_t children) {
  std::vector<Bitset> scratch;
  return box_counts(curd, children, scratch);
}

std::optional<LineFit> fit_box_dimension(const std::vector<uint64_t>& counts, int base) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  int n = 0;
  for (size_t j = 0; j < counts.size(); ++j) {
    if (counts[j] == 0) continue;
    const double x = static_cast<double>(j) * std::log(static_cast<double>(base));
    const double y = std::log(static_cast<double>(counts[j]));
    sx += x, sy += y, sxx += x * x, sxy += x * y, syy += y * y;
    ++n;
  }
  if (n < 2) return std::nullopt;
  const double vx = sxx - sx * sx / n, vy = syy - sy * sy / n, cxy = sxy - sx * sy / n;
  LineFit fit;
  fit.slope = cxy / vx;
  fit.r2 = vy > 0 ? (cxy * cxy) / (vx * vy) : 1.0;
  fit.points = n;
  return fit;
}

}  // namespace curdle
