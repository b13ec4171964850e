#include "curdle/extinction.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "curdle/box_levels.h"
#include "curdle/cell_shapes.h"
#include "curdle/theory.h"

namespace curdle {
namespace {

using Span = CellSpan;
using Shape = CellShape;

// Exact mode's cells cut by the view take the hypergeometric sum up to this many children
// (B^2 terms); above it, sampling with replacement, which differs by O(1/B).
constexpr uint64_t kExactUpTo = 512;

double log_choose(double n, double k) {
  return std::lgamma(n + 1) - std::lgamma(k + 1) - std::lgamma(n - k + 1);
}

// E[prod of x over the chosen], `chosen` items drawn without replacement from `total`, of which
// groups[g].second have the value groups[g].first and the rest the value 1.
double hypergeometric_product(const std::vector<std::pair<double, uint64_t>>& groups,
                              uint64_t total, uint64_t chosen) {
  std::vector<double> weight(chosen + 1, 0.0);  // by how many remain to be chosen
  weight[chosen] = 1;
  double left = static_cast<double>(total);
  for (const auto& [x, count] : groups) {
    const double n = static_cast<double>(count);
    std::vector<double> next(chosen + 1, 0.0);
    for (uint64_t r = 0; r <= chosen; ++r) {
      if (weight[r] == 0) continue;
      for (uint64_t j = 0; j <= std::min<uint64_t>(count, r); ++j) {
        const double rest = left - n, need = static_cast<double>(r - j);
        if (need > rest) continue;
        const double h = std::exp(log_choose(n, static_cast<double>(j)) + log_choose(rest, need) -
                                  log_choose(left, static_cast<double>(r)));
        next[r - j] += weight[r] * h * std::pow(x, static_cast<double>(j));
      }
    }
    weight = std::move(next);
    left -= n;
  }
  double sum = 0;  // the rest are outside the view: value 1, whatever is still to choose
  for (double w : weight) sum += w;
  return sum;
}

}  // namespace

ExtinctionChance::ExtinctionChance(const Lattice& l, std::vector<Probability> p)
    : l_(l), p_(std::move(p)) {}

double ExtinctionChance::operator()(int k, const CellShape& shape) {
  if (k == l_.stages) return 0.0;
  const auto key = std::make_pair(k, shape);
  if (const auto it = memo_.find(key); it != memo_.end()) return it->second;
  const int64_t side = static_cast<int64_t>(l_.side_in_cells(k));
  std::array<std::map<Span, uint64_t>, 3> axes;
  for (int d = 0; d < l_.dimension; ++d) axes[d] = child_spans(shape[d], side, l_.base);
  const double p = p_[static_cast<size_t>(k)].value();
  std::vector<std::pair<double, uint64_t>> groups;
  for (const auto& [child, n] : shapes(axes, l_.dimension))
    groups.push_back({(*this)(k + 1, child), n});
  double e = 1;
  const uint64_t B = l_.children();
  const auto m = static_cast<uint64_t>(std::llround(p * static_cast<double>(B)));
  if (l_.mode == Mode::exact && groups.size() == 1 && groups[0].second == B) {
    e = std::pow(groups[0].first, static_cast<double>(m));  // all m chosen children alike
  } else if (l_.mode == Mode::exact && B <= kExactUpTo) {
    e = hypergeometric_product(groups, B, m);
  } else {  // canonical, quota, and exact cut cells of over kExactUpTo children (O(1/B) off)
    for (const auto& [x, n] : groups) e *= std::pow(1 - p * (1 - x), static_cast<double>(n));
  }
  return memo_[key] = e;
}

namespace {

std::vector<double> expected_counts(const Lattice& l, const std::vector<Probability>& p,
                                    const Box& view, bool weighted) {
  ExtinctionChance extinction(l, p);
  std::vector<double> out;
  for (int k = 0; k <= l.stages; ++k) {
    const int64_t side = static_cast<int64_t>(l.side_in_cells(k));
    std::array<std::map<Span, uint64_t>, 3> axes;
    for (int d = 0; d < l.dimension; ++d)
      axes[d] = spans_meeting(view.origin[d], view.origin[d] + view.size[d], side);
    double kept = 0;
    for (const auto& [shape, n] : shapes(axes, l.dimension)) {
      double share = 1;  // of the cell's cells inside the view
      for (int d = 0; d < l.dimension; ++d)
        share *= static_cast<double>(shape[d].second - shape[d].first) / static_cast<double>(side);
      kept += static_cast<double>(n) * (weighted ? share : 1.0) * (1 - extinction(k, shape));
    }
    out.push_back(survival_probability(p, k) * kept);
  }
  return out;
}

}  // namespace

std::vector<double> expected_box_counts(const Lattice& l, const std::vector<Probability>& p,
                                        const Box& view) {
  return expected_counts(l, p, view, false);
}

std::vector<double> expected_share_weighted_box_counts(const Lattice& l,
                                                       const std::vector<Probability>& p,
                                                       const Box& view) {
  return expected_counts(l, p, view, true);
}

std::vector<double> share_weighted_box_counts(const Lattice& l, const Box& view,
                                              const std::vector<bool>& cells) {
  std::vector<double> out(static_cast<size_t>(l.stages + 1), 0.0);
  // Level j of the pyramid is stage K - j; a box weighs the share of its cells in the view.
  for_each_box_level(l.base, l.dimension, view, cells, l.stages, [&](const BoxLevel& level) {
    double sum = 0;
    for_each_occupied(level, [&](const std::array<int64_t, 3>& at) {
      double share = 1;
      for (int d = 0; d < l.dimension; ++d) {
        const int64_t lo = std::max(at[d] * level.side, view.origin[d]);
        const int64_t hi = std::min((at[d] + 1) * level.side, view.origin[d] + view.size[d]);
        share *= static_cast<double>(hi - lo) / static_cast<double>(level.side);
      }
      sum += share;
    });
    out[static_cast<size_t>(l.stages - level.index)] = sum;
  });
  return out;
}

}  // namespace curdle
