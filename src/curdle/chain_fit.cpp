#include "curdle/chain_fit.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace curdle {
namespace {

using Row = std::vector<double>;
using Matrix = std::vector<Row>;

constexpr int kMostRounds = 20000;
constexpr double kConverged = 1e-10;  // EM stops when a round gains less, relative to |log L|
constexpr double kZero = 1e-8;        // an entry fitted below this is taken as 0
constexpr double kStep = 1e-4;        // of the log-ratio coordinates, for the Hessian
constexpr double kZ95 = 1.959963984540054;
constexpr double kInterval95 = 3.841458820694124;             // chi-square, 1 degree, upper 5 %
constexpr uint64_t kMostInformationWork = uint64_t{1} << 31;  // parameters x leaves

// The chain being fitted: the start row and one matrix per block (1, or K when stage-wise).
struct Parameters {
  Row start;
  std::vector<Matrix> blocks;
};

ChainValues expand(const Parameters& p, int K) {
  ChainValues v;
  v.start = p.start;
  for (int k = 0; k < K; ++k)
    v.transitions.push_back(p.blocks.size() == 1 ? p.blocks[0] : p.blocks[static_cast<size_t>(k)]);
  return v;
}

// The counts of each block's steps: a stage's own, or every stage's together.
std::vector<Matrix> block_counts(const StateTreeCounts& c, size_t blocks) {
  if (blocks == c.steps.size()) return c.steps;
  Matrix sum(c.roots.size(), Row(c.roots.size(), 0.0));
  for (const Matrix& m : c.steps)
    for (size_t i = 0; i < m.size(); ++i)
      for (size_t j = 0; j < m.size(); ++j) sum[i][j] += m[i][j];
  return {sum};
}

Row shares(const Row& counts, const Row& otherwise) {
  const double n = std::accumulate(counts.begin(), counts.end(), 0.0);
  if (!(n > 0)) return otherwise;
  Row out(counts.size());
  for (size_t j = 0; j < counts.size(); ++j) out[j] = counts[j] / n;
  return out;
}

Row absorbing(size_t S) {
  Row r(S, 0.0);
  r[0] = 1;
  return r;
}

// The M step: each fitted row to its counts' shares.
Parameters maximise(const StateTreeCounts& c, const Parameters& was, const ChainFitOptions& o) {
  Parameters p = was;
  const size_t S = c.roots.size();
  if (!o.start_state) {
    Row living = c.roots;  // a root is never dead (markov.h)
    living[0] = 0;
    p.start = shares(living, was.start);
  }
  const std::vector<Matrix> counts = block_counts(c, was.blocks.size());
  for (size_t b = 0; b < p.blocks.size(); ++b)
    for (size_t i = 0; i < S; ++i)
      p.blocks[b][i] = i == 0 && !o.wheys ? absorbing(S) : shares(counts[b][i], was.blocks[b][i]);
  return p;
}

// The start EM works from: each coarser cell labelled by the commonest living state among its
// children (dead when they all are), the steps so labelled counted, half a step added to every
// entry EM may fit.
Parameters first_guess(const StateTree& t, const ChainFitOptions& o, size_t blocks) {
  const size_t S = t.states();
  const int K = t.stages();
  StateTreeCounts c;
  c.roots.assign(S, 0.5);
  c.steps.assign(static_cast<size_t>(K), Matrix(S, Row(S, 0.5)));
  std::vector<uint8_t> below(t.leaves());
  for (size_t i = 0; i < below.size(); ++i) below[i] = t.leaf(i);
  for (int k = K; k >= 1; --k) {
    std::vector<std::vector<uint32_t>> votes(t.cells(k - 1), std::vector<uint32_t>(S, 0));
    for (size_t i = 0; i < below.size(); ++i) ++votes[t.parent(k, i)][below[i]];
    std::vector<uint8_t> above(votes.size(), 0);
    for (size_t n = 0; n < votes.size(); ++n) {
      uint32_t most = 0;
      for (size_t s = 1; s < S; ++s)
        if (votes[n][s] > most) most = votes[n][s], above[n] = static_cast<uint8_t>(s);
    }
    for (size_t i = 0; i < below.size(); ++i)
      c.steps[static_cast<size_t>(k) - 1][above[t.parent(k, i)]][below[i]] += 1;
    below.swap(above);
  }
  for (const uint8_t s : below) c.roots[s] += 1;
  Parameters none;
  none.start.assign(S, 1.0 / static_cast<double>(S - 1));
  none.start[0] = 0;
  if (o.start_state) none.start.assign(S, 0.0), none.start[*o.start_state] = 1;
  none.blocks.assign(blocks, Matrix(S, Row(S, 1.0 / static_cast<double>(S))));
  return maximise(c, none, o);
}

// Every entry of the chain, flattened, for extrapolation.
std::vector<double*> entries_of(Parameters& p) {
  std::vector<double*> out;
  for (double& x : p.start) out.push_back(&x);
  for (Matrix& m : p.blocks)
    for (Row& r : m)
      for (double& x : r) out.push_back(&x);
  return out;
}

// SQUAREM's step from p0 through two EM rounds p1, p2: p0 - 2 a r + a^2 v, r = p1 - p0,
// v = p2 - 2 p1 + p0, a = -|r| / |v| (at most -1), each row then put back on the simplex.
// False when the rounds did not move.
bool extrapolate(const Parameters& p0, const Parameters& p1, const Parameters& p2,
                 Parameters& out) {
  Parameters a = p0, b = p1, c = p2;
  out = p0;
  const std::vector<double*> x0 = entries_of(a), x1 = entries_of(b), x2 = entries_of(c),
                             x = entries_of(out);
  double rr = 0, vv = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const double r = *x1[i] - *x0[i], v = *x2[i] - 2 * *x1[i] + *x0[i];
    rr += r * r, vv += v * v;
  }
  if (!(rr > 0) || !(vv > 0)) return false;
  const double step = std::min(-1.0, -std::sqrt(rr / vv));
  for (size_t i = 0; i < x.size(); ++i) {
    const double r = *x1[i] - *x0[i], v = *x2[i] - 2 * *x1[i] + *x0[i];
    *x[i] = std::max(0.0, *x0[i] - 2 * step * r + step * step * v);
  }
  auto simplex = [](Row& r) {
    const double n = std::accumulate(r.begin(), r.end(), 0.0);
    for (double& e : r) e /= n;
  };
  simplex(out.start);
  for (Matrix& m : out.blocks)
    for (Row& r : m) simplex(r);
  return true;
}

// One matrix per stage leaves the labels of the hidden stages free: swapping two states' names at
// stage k (the rows of P_(k+1), the columns of P_k) draws the same pictures. The fit names them as
// a designer reads a chain: from the finest stage up, each stage's states are named so that a
// cell's children most often keep its state (the largest sum of P_(k+1)[i][i]). Dead keeps its
// name unless it revives.
void name_hidden_states(Parameters& p, bool wheys) {
  const size_t S = p.start.size();
  const size_t first = wheys ? 0 : 1;
  if (S - first > 8) return;  // 8! orders at most
  for (size_t k = p.blocks.size(); k-- > 0;) {
    const Matrix& down = p.blocks[k];
    std::vector<size_t> order(S), best(S);
    std::iota(order.begin(), order.end(), 0);
    best = order;
    double most = -1;
    do {
      double kept = 0;
      for (size_t i = first; i < S; ++i) kept += down[order[i]][i];
      if (kept > most + 1e-12) most = kept, best = order;
    } while (
        std::next_permutation(order.begin() + static_cast<std::ptrdiff_t>(first), order.end()));
    Matrix rows = down;
    for (size_t i = 0; i < S; ++i) p.blocks[k][i] = rows[best[i]];
    if (k > 0) {
      for (Row& r : p.blocks[k - 1]) {
        const Row was = r;
        for (size_t i = 0; i < S; ++i) r[i] = was[best[i]];
      }
    } else {
      const Row was = p.start;
      for (size_t i = 0; i < S; ++i) p.start[i] = was[best[i]];
    }
  }
}

// The start's entries, given the rows: the roots' states are a mixture whose components (each
// root's chance of its leaves in each state) the rows fix. Each entry's interval is where the
// profile likelihood, the other entries at their best for it, stays within the chi-square point:
// a root's state is often all but forgotten after a few stages, and the curvature at the best
// start says little then.
double start_log_likelihood(const std::vector<double>& leaves, const Row& start) {
  const size_t S = start.size();
  double sum = 0;
  for (size_t r = 0; r * S < leaves.size(); ++r) {
    double l = 0;
    for (size_t i = 0; i < S; ++i) l += start[i] * leaves[r * S + i];
    sum += std::log(std::max(l, 1e-300));
  }
  return sum;
}

double start_profile(const std::vector<double>& leaves, const Row& best, size_t j, double c) {
  const size_t S = best.size();
  Row q = best;
  double rest = 0;
  for (size_t i = 1; i < S; ++i) rest += i == j ? 0.0 : q[i];
  for (size_t i = 1; i < S; ++i)
    q[i] = i == j ? c : (rest > 0 ? q[i] / rest * (1 - c) : (1 - c) / static_cast<double>(S - 2));
  for (int round = 0; round < 200 && S > 3; ++round) {
    Row share(S, 0.0);
    for (size_t r = 0; r * S < leaves.size(); ++r) {
      double l = 0;
      for (size_t i = 0; i < S; ++i) l += q[i] * leaves[r * S + i];
      if (l <= 0) continue;
      for (size_t i = 1; i < S; ++i)
        if (i != j) share[i] += q[i] * leaves[r * S + i] / l;
    }
    double total = 0;
    for (size_t i = 1; i < S; ++i) total += share[i];
    if (!(total > 0)) break;
    for (size_t i = 1; i < S; ++i)
      if (i != j) q[i] = share[i] / total * (1 - c);
  }
  return start_log_likelihood(leaves, q);
}

std::pair<double, double> start_interval(const std::vector<double>& leaves, const Row& best,
                                         size_t j) {
  const double floor = start_log_likelihood(leaves, best) - kInterval95 / 2;
  auto bound = [&](double inside, double outside) {
    if (start_profile(leaves, best, j, outside) >= floor) return outside;
    for (int i = 0; i < 40; ++i) {
      const double mid = (inside + outside) / 2;
      (start_profile(leaves, best, j, mid) >= floor ? inside : outside) = mid;
    }
    return inside;
  };
  return {bound(best[j], 0.0), bound(best[j], 1.0)};
}

// A free coordinate of the information matrix: entry `entry` of a row (`block` -1: the start)
// against the row's reference entry, its largest.
struct Coordinate {
  int block;
  size_t row, entry;
};

Row& row_of(Parameters& p, const Coordinate& c) {
  return c.block < 0 ? p.start : p.blocks[static_cast<size_t>(c.block)][c.row];
}

size_t reference_of(const Row& r) {
  return static_cast<size_t>(std::max_element(r.begin(), r.end()) - r.begin());
}

// The gradient of log L in the coordinates: per row, n_t - N P_t (Fisher's identity).
std::vector<double> score(const StateTree& t, const Parameters& p,
                          const std::vector<Coordinate>& coords, double* log_likelihood) {
  const StateTreeCounts c = t.expected_counts(expand(p, t.stages()));
  if (log_likelihood) *log_likelihood = c.log_likelihood;
  const std::vector<Matrix> counts = block_counts(c, p.blocks.size());
  std::vector<double> g;
  for (const Coordinate& x : coords) {
    const Row& n = x.block < 0 ? c.roots : counts[static_cast<size_t>(x.block)][x.row];
    const Row& P = x.block < 0 ? p.start : p.blocks[static_cast<size_t>(x.block)][x.row];
    g.push_back(n[x.entry] - std::accumulate(n.begin(), n.end(), 0.0) * P[x.entry]);
  }
  return g;
}

// The row with coordinate `entry` moved by h: P_t e^h, renormalised.
void tilt(Row& r, size_t entry, double h) {
  const double z = 1 - r[entry] + r[entry] * std::exp(h);
  for (size_t j = 0; j < r.size(); ++j) r[j] = (j == entry ? r[j] * std::exp(h) : r[j]) / z;
}

// The inverse of a symmetric positive definite matrix (Cholesky); a small ridge is added until it
// is one, so that directions the data do not fix get a huge variance instead of none.
Matrix inverse(Matrix a) {
  const size_t n = a.size();
  double scale = 0;
  for (size_t i = 0; i < n; ++i) scale = std::max(scale, std::fabs(a[i][i]));
  for (double ridge = 0; ridge <= scale; ridge = ridge ? ridge * 100 : scale * 1e-12) {
    Matrix L(n, Row(n, 0.0));
    bool positive = true;
    for (size_t j = 0; j < n && positive; ++j) {
      double d = a[j][j] + ridge;
      for (size_t k = 0; k < j; ++k) d -= L[j][k] * L[j][k];
      if (!(d > 0)) positive = false, d = 1;
      L[j][j] = std::sqrt(d);
      for (size_t i = j + 1; i < n; ++i) {
        double s = a[i][j];
        for (size_t k = 0; k < j; ++k) s -= L[i][k] * L[j][k];
        L[i][j] = s / L[j][j];
      }
    }
    if (!positive) continue;
    Matrix inv(n, Row(n, 0.0));
    for (size_t col = 0; col < n; ++col) {
      Row y(n, 0.0);
      for (size_t i = 0; i < n; ++i) {
        double s = i == col ? 1.0 : 0.0;
        for (size_t k = 0; k < i; ++k) s -= L[i][k] * y[k];
        y[i] = s / L[i][i];
      }
      for (size_t i = n; i-- > 0;) {
        double s = y[i];
        for (size_t k = i + 1; k < n; ++k) s -= L[k][i] * inv[k][col];
        inv[i][col] = s / L[i][i];
      }
    }
    return inv;
  }
  return Matrix(n, Row(n, INFINITY));
}

// Wilson's 95 % interval for a share p seen over an effective count n.
std::pair<double, double> wilson(double p, double n) {
  if (!(n > 0) || !std::isfinite(n)) return {0.0, 1.0};
  const double z2 = kZ95 * kZ95, d = 1 + z2 / n;
  const double centre = (p + z2 / (2 * n)) / d;
  const double half = kZ95 / d * std::sqrt(std::max(0.0, p * (1 - p) / n + z2 / (4 * n * n)));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

// An entry fitted as 0 has no curvature to go by: its upper bound is where moving that much of its
// row's mass into it, (1 - e) row + e [entry], costs the likelihood-ratio test's 95 % point
// (log L down by 1.92), found by doubling e and then halving the bracket.
double zero_entry_high(const StateTree& t, const Parameters& p, int block, size_t row, size_t entry,
                       double best) {
  const double floor = best - kInterval95 / 2;
  auto log_l = [&](double e) {
    Parameters q = p;
    Row& r = block < 0 ? q.start : q.blocks[static_cast<size_t>(block)][row];
    for (double& x : r) x *= 1 - e;
    r[entry] += e;
    return t.expected_counts(expand(q, t.stages())).log_likelihood;
  };
  double lo = 0, hi = 1e-6;
  while (hi < 1 && log_l(hi) >= floor) lo = hi, hi = std::min(1.0, hi * 4);
  if (hi >= 1 && log_l(1) >= floor) return 1;
  for (int i = 0; i < 30 && hi - lo > 1e-4 * hi; ++i) {
    const double mid = (lo + hi) / 2;
    (log_l(mid) >= floor ? lo : hi) = mid;
  }
  return hi;
}

// Each fitted entry's interval from the covariance of the coordinates.
void set_intervals(ChainFit& fit, const StateTree& t, const Parameters& p,
                   const std::vector<Coordinate>& coords, const Matrix& cov) {
  auto place = [&](std::vector<FittedEntry>& out, const Row& P, int block, size_t row) {
    std::vector<size_t> mine;  // this row's coordinates
    for (size_t a = 0; a < coords.size(); ++a)
      if (coords[a].block == block && (block < 0 || coords[a].row == row)) mine.push_back(a);
    for (size_t e = 0; e < P.size(); ++e) {
      FittedEntry& f = out[e];
      if (f.fixed) continue;
      if (P[e] < kZero) {
        f.low = 0, f.high = zero_entry_high(t, p, block, row, e, fit.log_likelihood);
        continue;
      }
      double var = 0;
      for (const size_t a : mine)
        for (const size_t b : mine) {
          const size_t u = coords[a].entry, v = coords[b].entry;
          const double gu = P[e] * ((e == u) - P[u]), gv = P[e] * ((e == v) - P[v]);
          var += gu * cov[a][b] * gv;
        }
      const double n_eff = var > 0 ? P[e] * (1 - P[e]) / var : INFINITY;
      std::tie(f.low, f.high) =
          P[e] * (1 - P[e]) > 0 ? wilson(P[e], n_eff) : std::pair<double, double>{P[e], P[e]};
    }
  };
  place(fit.start, p.start, -1, 0);
  if (!fit.start[0].fixed || fit.start.size() > 2) {
    const std::vector<double> leaves = t.expected_counts(expand(p, t.stages())).root_leaves;
    for (size_t j = 1; j < fit.start.size(); ++j)
      if (!fit.start[j].fixed)
        std::tie(fit.start[j].low, fit.start[j].high) = start_interval(leaves, p.start, j);
  }
  for (size_t b = 0; b < p.blocks.size(); ++b)
    for (size_t i = 0; i < p.blocks[b].size(); ++i)
      place(fit.transitions[b][i], p.blocks[b][i], static_cast<int>(b), i);
  fit.intervals = true;
}

void take_intervals(ChainFit& fit, const StateTree& t, const Parameters& p,
                    const ChainFitOptions& o) {
  std::vector<Coordinate> coords;
  auto add_row = [&](int block, size_t row, const Row& r) {
    const size_t ref = reference_of(r);
    for (size_t e = 0; e < r.size(); ++e)
      if (e != ref && r[e] >= kZero) coords.push_back({block, row, e});
  };
  if (!o.start_state) add_row(-1, 0, p.start);
  for (size_t b = 0; b < p.blocks.size(); ++b)
    for (size_t i = 0; i < p.blocks[b].size(); ++i)
      if (i != 0 || o.wheys) add_row(static_cast<int>(b), i, p.blocks[b][i]);
  if (coords.size() * t.leaves() > kMostInformationWork) return;
  const size_t d = coords.size();
  Matrix info(d, Row(d, 0.0));
  for (size_t a = 0; a < d; ++a) {
    Parameters up = p, down = p;
    tilt(row_of(up, coords[a]), coords[a].entry, kStep);
    tilt(row_of(down, coords[a]), coords[a].entry, -kStep);
    const std::vector<double> su = score(t, up, coords, nullptr);
    const std::vector<double> sd = score(t, down, coords, nullptr);
    for (size_t b = 0; b < d; ++b) info[b][a] = -(su[b] - sd[b]) / (2 * kStep);
  }
  for (size_t a = 0; a < d; ++a)
    for (size_t b = 0; b < a; ++b) info[a][b] = info[b][a] = (info[a][b] + info[b][a]) / 2;
  set_intervals(fit, t, p, coords, inverse(info));
}

}  // namespace

ChainValues ChainFit::values(int stages) const {
  ChainValues v;
  for (const FittedEntry& e : start) v.start.push_back(e.value);
  for (int k = 0; k < stages; ++k) {
    const auto& m = transitions.size() == 1 ? transitions[0] : transitions[static_cast<size_t>(k)];
    Matrix out;
    for (const auto& row : m) {
      out.emplace_back();
      for (const FittedEntry& e : row) out.back().push_back(e.value);
    }
    v.transitions.push_back(out);
  }
  return v;
}

double information_criterion(double log_likelihood, int parameters, uint64_t leaves) {
  return -2 * log_likelihood +
         parameters * std::log(static_cast<double>(std::max<uint64_t>(leaves, 1)));
}

ChainFit fit_chain(const StateTree& t, const ChainFitOptions& o) {
  const size_t S = t.states();
  const size_t blocks = o.stage_wise ? static_cast<size_t>(t.stages()) : 1;
  Parameters p = first_guess(t, o, blocks);
  ChainFit fit;
  // EM, each pair of rounds extrapolated by SQUAREM (Varadhan and Roland 2008, scheme 3): a
  // direction the leaves hardly fix (the start, after many stages of mixing) takes EM thousands of
  // rounds alone; the extrapolation is kept only when it does not lower the likelihood.
  auto round = [&](const Parameters& at, double& log_l) {
    const StateTreeCounts c = t.expected_counts(expand(at, t.stages()));
    log_l = c.log_likelihood;
    ++fit.iterations;
    return maximise(c, at, o);
  };
  double last = -INFINITY;
  while (fit.iterations < kMostRounds) {
    double l0 = 0, l1 = 0, l3 = 0;
    const Parameters p1 = round(p, l0);
    const double gain = l0 - last;
    if (std::isfinite(last) && gain >= 0 && gain <= kConverged * std::max(1.0, std::fabs(l0))) {
      fit.converged = true;
      break;
    }
    last = l0;
    const Parameters p2 = round(p1, l1);
    Parameters jump;
    if (!extrapolate(p, p1, p2, jump)) {
      p = p2;
      continue;
    }
    const Parameters p3 = round(jump, l3);
    p = std::isfinite(l3) && l3 >= l0 ? p3 : p2;
  }
  if (!fit.converged) {
    double l = 0;
    (void)round(p, l);
    last = l;
  }
  fit.log_likelihood = last;
  // Entries EM drove to nothing are nothing.
  auto clean = [](Row& r) {
    for (double& x : r) x = x < kZero ? 0.0 : x;
    const double n = std::accumulate(r.begin(), r.end(), 0.0);
    for (double& x : r) x /= n;
  };
  clean(p.start);
  for (Matrix& m : p.blocks)
    for (Row& r : m) clean(r);
  if (o.stage_wise && !o.start_state) name_hidden_states(p, o.wheys);
  fit.parameters =
      static_cast<int>((o.start_state ? 0 : S - 2) + blocks * (S - (o.wheys ? 0 : 1)) * (S - 1));
  fit.bic = information_criterion(fit.log_likelihood, fit.parameters, t.leaves());
  auto entries = [](const Row& r, bool fixed) {
    std::vector<FittedEntry> out;
    for (const double x : r) out.push_back({x, x, x, fixed});
    return out;
  };
  fit.start = entries(p.start, o.start_state.has_value());
  fit.start[0].fixed = true;
  for (const Matrix& m : p.blocks) {
    fit.transitions.emplace_back();
    for (size_t i = 0; i < S; ++i)
      fit.transitions.back().push_back(entries(m[i], i == 0 && !o.wheys));
  }
  if (o.intervals) take_intervals(fit, t, p, o);
  return fit;
}

}  // namespace curdle
