#include "curdle/boxcount.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cmath>
#include <functional>

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
    const Bitset& stage = curd.stages[j];
    alive.assign_zero(stage.size);
    // Only survivors of stage j can have surviving descendants. Ranges of whole words, so
    // that tasks write disjoint words.
    // When b^E divides 64 a cell's children are a field of one word: test it directly.
    const bool in_one_word = 64 % children == 0;
    const uint64_t field = children >= 64 ? ~uint64_t{0} : (uint64_t{1} << children) - 1;
    auto mark = [&](uint64_t begin, uint64_t end) {
      uint64_t n = 0;
      for_each_set(stage, begin, end, [&](uint64_t i) {
        const uint64_t first = i * children;
        const bool any = in_one_word ? ((below->words[first >> 6] >> (first & 63)) & field) != 0
                                     : below->any_in(first, first + children);
        if (any) {
          alive.set(i);
          ++n;
        }
      });
      return n;
    };
    constexpr uint64_t kBitsPerTask = 64 * 1024;
    if (stage.size <= kBitsPerTask) {
      counts[j] = mark(0, stage.size);
    } else {
      counts[j] = tbb::parallel_reduce(
          tbb::blocked_range<uint64_t>(0, (stage.size + kBitsPerTask - 1) / kBitsPerTask), uint64_t{0},
          [&](const tbb::blocked_range<uint64_t>& r, uint64_t n) {
            return n + mark(r.begin() * kBitsPerTask, std::min(stage.size, r.end() * kBitsPerTask));
          },
          std::plus<>());
    }
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
