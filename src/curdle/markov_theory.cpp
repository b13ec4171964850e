#include "curdle/markov_theory.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>

#include "curdle/cell_shapes.h"
#include "curdle/theory.h"

namespace curdle {
namespace {

using Matrix = std::vector<std::vector<double>>;

Matrix values_of(const std::vector<std::vector<Probability>>& m) {
  Matrix out(m.size(), std::vector<double>(m.size()));
  for (size_t i = 0; i < m.size(); ++i)
    for (size_t j = 0; j < m.size(); ++j) out[i][j] = m[i][j].value();
  return out;
}

Matrix identity(size_t n) {
  Matrix m(n, std::vector<double>(n, 0.0));
  for (size_t i = 0; i < n; ++i) m[i][i] = 1;
  return m;
}

Matrix times(const Matrix& a, const Matrix& b) {
  Matrix m(a.size(), std::vector<double>(a.size(), 0.0));
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t t = 0; t < a.size(); ++t)
      for (size_t j = 0; j < a.size(); ++j) m[i][j] += a[i][t] * b[t][j];
  return m;
}

// E[f(x) f(y)] for two given distinct children x, y of a cell, from mean = E[f(x)] and
// square = E[f(x)^2] over one child: independent (canonical) or dealt without replacement
// (exact: (B^2 mean^2 - B square) / (B (B - 1))).
double sibling_pair(const Lattice& l, double mean, double square) {
  if (l.mode != Mode::exact) return mean * mean;
  const double B = static_cast<double>(l.children());
  if (B < 2) return square;
  return (B * B * mean * mean - B * square) / (B * (B - 1));
}

// The exact deal below is followed in a table of at most this many count vectors, and at most
// this many table entries over all the children (a few milliseconds).
constexpr uint64_t kDealtTable = uint64_t{1} << 20;
constexpr uint64_t kDealtWork = uint64_t{1} << 24;

// Exact mode deals a state-i parent's B children the states of a fixed multiset, n_t = P[i][t] B
// of each, in random order; the children inside the view (`inside`: each group's chance of no
// target per state, and how many children it has) take the first of them, so that
//   E[prod over inside children of f(state)]
// follows child by child over how many of each state are still to deal (a mixed-radix count
// vector), each child taking state t with (still to deal of t) / (still to deal). Empty when that
// table is too large (many children in many states): the caller then draws with replacement,
// O(1/B) off.
std::optional<double> dealt_product(
    uint64_t B, const std::vector<Probability>& row,
    const std::vector<std::pair<std::vector<double>, uint64_t>>& inside) {
  const size_t n = row.size();
  std::vector<uint64_t> deal(n, 0), radix(n, 1);
  uint64_t living = 0;
  for (size_t t = 1; t < n; ++t) living += deal[t] = row[t].round_times(B);
  if (living > B) return std::nullopt;
  deal[0] = B - living;
  uint64_t table = 1, children = 0;
  for (size_t t = 0; t < n; ++t) {
    radix[t] = table;
    if (table > kDealtTable / (deal[t] + 1)) return std::nullopt;
    table *= deal[t] + 1;
  }
  for (const auto& group : inside) children += group.second;
  if (children > B || table * children > kDealtWork) return std::nullopt;
  // weight[index of the counts already dealt]
  std::vector<double> weight(table, 0.0), next(table);
  weight[0] = 1;
  uint64_t dealt = 0;
  for (const auto& [f, count] : inside)
    for (uint64_t c = 0; c < count; ++c, ++dealt) {
      std::fill(next.begin(), next.end(), 0.0);
      const double left = static_cast<double>(B - dealt);
      for (uint64_t index = 0; index < table; ++index) {
        if (weight[index] == 0) continue;
        for (size_t t = 0; t < n; ++t) {
          const uint64_t used = index / radix[t] % (deal[t] + 1);
          if (used == deal[t]) continue;
          next[index + radix[t]] +=
              weight[index] * static_cast<double>(deal[t] - used) / left * f[t];
        }
      }
      std::swap(weight, next);
    }
  double sum = 0;
  for (const double w : weight) sum += w;
  return sum;
}

// The chance that a cell in each state leaves no finest cell of `targets` in the view, for
// cells of a given stage and inside shape (memoised: a level has at most 3^E shapes).
class StateExtinction {
 public:
  StateExtinction(const Lattice& l, const MarkovChain& chain, const std::vector<bool>& targets)
      : l_(l), chain_(chain), targets_(targets) {}

  const std::vector<double>& operator()(int k, const CellShape& shape) {
    const auto key = std::make_pair(k, shape);
    if (const auto it = memo_.find(key); it != memo_.end()) return it->second;
    const size_t n = targets_.size();
    std::vector<double> e(n, 1.0);
    if (k == l_.stages) {
      for (size_t i = 0; i < n; ++i) e[i] = targets_[i] ? 0.0 : 1.0;
      return memo_[key] = e;
    }
    const int64_t side = static_cast<int64_t>(l_.side_in_cells(k));
    std::array<std::map<CellSpan, uint64_t>, 3> axes;
    bool whole = true;
    for (int d = 0; d < l_.dimension; ++d) {
      axes[d] = child_spans(shape[d], side, l_.base);
      whole &= shape[d] == CellSpan{0, side};
    }
    const std::vector<std::pair<CellShape, uint64_t>> children = shapes(axes, l_.dimension);
    for (size_t i = 0; i < n; ++i) {
      const auto& row = chain_.row(k + 1, static_cast<uint32_t>(i));
      if (l_.mode == Mode::exact && whole) {
        const std::vector<double> child = (*this)(k + 1, children[0].first);
        for (size_t t = 0; t < n; ++t)
          e[i] *= std::pow(child[t], static_cast<double>(row[t].round_times(l_.children())));
        continue;
      }
      std::vector<std::pair<std::vector<double>, uint64_t>> inside;
      for (const auto& [shape_c, count] : children)
        inside.push_back({(*this)(k + 1, shape_c), count});
      if (l_.mode == Mode::exact) {
        if (const std::optional<double> dealt = dealt_product(l_.children(), row, inside)) {
          e[i] = *dealt;
          continue;
        }
      }
      for (const auto& [child, count] : inside) {
        double none = 0;
        for (size_t t = 0; t < n; ++t) none += row[t].value() * child[t];
        e[i] *= std::pow(none, static_cast<double>(count));
      }
    }
    return memo_[key] = e;
  }

 private:
  const Lattice& l_;
  const MarkovChain& chain_;
  std::vector<bool> targets_;
  std::map<std::pair<int, CellShape>, std::vector<double>> memo_;
};

CellShape whole_cell(const Lattice& l, int k) {
  CellShape s{CellSpan{0, 1}, CellSpan{0, 1}, CellSpan{0, 1}};
  for (int d = 0; d < l.dimension; ++d) s[d] = {0, static_cast<int64_t>(l.side_in_cells(k))};
  return s;
}

}  // namespace

std::vector<double> state_count_sd(const Lattice& l, const MarkovChain& chain, int k,
                                   const Box& box) {
  const size_t n = chain.start.size();
  const double C = static_cast<double>(cells_meeting(l, k, box));
  const std::vector<double> s_k = state_shares(chain, k);
  std::vector<double> var(n);
  for (size_t j = 0; j < n; ++j) var[j] = C * s_k[j] * (1 - s_k[j]);
  // From the top down: Q = P_(m+2) ... P_k, so that a sibling's chance of ending in j is
  // PQ[x][j] with PQ = P_(m+1) Q, and E[f(x) f(y)] over two siblings needs PQ and P (Q o Q).
  Matrix Q = identity(n);
  std::vector<double> s_m = state_shares(chain, k - 1);
  for (int m = k - 1; m >= 0; --m) {
    const Matrix P = values_of(chain.transitions[static_cast<size_t>(m)]);  // P_(m+1)
    const Matrix PQ = times(P, Q);
    Matrix QQ = Q;
    for (auto& row : QQ)
      for (double& x : row) x *= x;
    const Matrix PQQ = times(P, QQ);
    const double T = sum_of_squares(l, k, m, box) - sum_of_squares(l, k, m + 1, box);
    for (size_t j = 0; j < n; ++j) {
      double c = 0;
      for (size_t i = 0; i < n; ++i) c += s_m[i] * sibling_pair(l, PQ[i][j], PQQ[i][j]);
      var[j] += T * (c - s_k[j] * s_k[j]);
    }
    Q = PQ;
    if (m > 0) s_m = state_shares(chain, m - 1);
  }
  std::vector<double> sd(n);
  for (size_t j = 0; j < n; ++j) sd[j] = var[j] > 0 ? std::sqrt(var[j]) : 0.0;
  return sd;
}

double extinction_chance(const Lattice& l, const MarkovChain& chain,
                         const std::vector<bool>& targets) {
  StateExtinction e(l, chain, targets);
  const std::vector<double>& root = e(0, whole_cell(l, 0));
  double chance = 0;
  for (size_t i = 0; i < root.size(); ++i) chance += chain.start[i].value() * root[i];
  return chance;
}

std::vector<double> expected_state_box_counts(const Lattice& l, const MarkovChain& chain,
                                              const std::vector<bool>& targets, const Box& view) {
  StateExtinction e(l, chain, targets);
  std::vector<double> counts;
  for (int m = 0; m <= l.stages; ++m) {
    const int64_t side = static_cast<int64_t>(l.side_in_cells(m));
    std::array<std::map<CellSpan, uint64_t>, 3> axes;
    for (int d = 0; d < l.dimension; ++d)
      axes[d] = spans_meeting(view.origin[d], view.origin[d] + view.size[d], side);
    const std::vector<double> s_m = state_shares(chain, m);
    double sum = 0;
    for (const auto& [shape, cells] : shapes(axes, l.dimension)) {
      const std::vector<double>& none = e(m, shape);
      double some = 0;
      for (size_t i = 0; i < s_m.size(); ++i) some += s_m[i] * (1 - none[i]);
      sum += static_cast<double>(cells) * some;
    }
    counts.push_back(sum);
  }
  return counts;
}

std::optional<double> stationary_dimension(const Lattice& l, const MarkovChain& chain,
                                           const std::vector<bool>& targets) {
  if (!chain.stationary()) return std::nullopt;
  const Matrix P = values_of(chain.transitions[0]);
  const size_t n = P.size();
  // The states that can reach a target: closure backwards along P's positive entries.
  std::vector<bool> feeds = targets;
  for (bool grew = true; grew;) {
    grew = false;
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < n && !feeds[i]; ++j)
        if (feeds[j] && P[i][j] > 0) feeds[i] = grew = true;
  }
  // rho of a reducible non-negative matrix is the largest over its strongly connected blocks
  // (Seneta 1981, ch. 1); each block's Perron root by power iteration on M + I, which is
  // primitive, squeezed between the Collatz-Wielandt bounds.
  const double B = static_cast<double>(l.children());
  std::vector<std::vector<bool>> reach(n, std::vector<bool>(n, false));
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) reach[i][j] = feeds[i] && feeds[j] && P[i][j] > 0;
  for (size_t m = 0; m < n; ++m)
    for (size_t i = 0; i < n; ++i)
      if (reach[i][m])
        for (size_t j = 0; j < n; ++j)
          if (reach[m][j]) reach[i][j] = true;
  double rho = 0;
  std::vector<bool> done(n, false);
  for (size_t i = 0; i < n; ++i) {
    if (!feeds[i] || done[i] || !reach[i][i]) continue;
    std::vector<size_t> block;
    for (size_t j = 0; j < n; ++j)
      if (j == i || (reach[i][j] && reach[j][i])) block.push_back(j), done[j] = true;
    std::vector<double> v(block.size(), 1.0);
    double lo = 0, hi = 0;
    for (int t = 0; t < 100000; ++t) {
      std::vector<double> w(block.size(), 0.0);
      lo = INFINITY, hi = 0;
      for (size_t a = 0; a < block.size(); ++a) {
        for (size_t c = 0; c < block.size(); ++c) w[a] += B * P[block[a]][block[c]] * v[c];
        lo = std::min(lo, w[a] / v[a]);
        hi = std::max(hi, w[a] / v[a]);
        w[a] += v[a];
      }
      if (hi - lo <= 1e-13 * hi) break;
      double norm = 0;
      for (double x : w) norm = std::max(norm, x);
      for (size_t a = 0; a < block.size(); ++a) v[a] = w[a] / norm;
    }
    rho = std::max(rho, (lo + hi) / 2);
  }
  const double log_rho = rho > 0 ? std::log(rho) : -INFINITY;
  if (log_rho <= 1e-12) return std::nullopt;
  return log_rho / std::log(static_cast<double>(l.base));
}

}  // namespace curdle
