#include "curdle/fit.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "curdle/box_levels.h"
#include "curdle/chi_square.h"
#include "curdle/extinction.h"
#include "curdle/probability.h"

namespace curdle {
namespace {

constexpr double kInterval95 = 3.841458820694124;  // chi-square, 1 degree, upper 5 %
constexpr double kSmallest = 1e-12;                // p is searched in [kSmallest, 1]
constexpr uint64_t kMostChildrenTested = 4096;     // parents with more are left out of the test
constexpr double kLeastExpected = 1;               // parents a bin of the test must expect
constexpr uint64_t kFewChildren = 100;  // stages with at most this many children in view are
                                        // given the split count's interval

// A parent's children by their inside part (sorted), how many of each, and its kind: parents
// whose children lie alike in the view share the likelihood and the distribution of a count.
using ChildClasses = std::vector<std::pair<CellShape, uint64_t>>;
using Occupied = std::vector<uint64_t>;  // occupied children per class
struct StageBranching {
  std::map<ChildClasses, std::map<Occupied, uint64_t>> parents;  // kind -> seen -> parents
  uint64_t parent_count = 0, child_count = 0;
};

// Along one axis, the children of parent box `at` that meet the view: index and inside part.
std::vector<std::pair<int64_t, CellSpan>> children_along(int64_t at, int base, int64_t side,
                                                         int64_t lo, int64_t hi) {
  std::vector<std::pair<int64_t, CellSpan>> out;
  for (int t = 0; t < base; ++t) {
    const int64_t c = at * base + t;
    const int64_t from = std::max(lo, c * side), to = std::min(hi, (c + 1) * side);
    if (to > from) out.push_back({c, {from - c * side, to - c * side}});
  }
  return out;
}

// How the occupied boxes of `parent` (stage k - 1) branch into those of `child` (stage k).
StageBranching branching(const Lattice& l, const Box& view, const BoxLevel& parent,
                         const BoxLevel& child) {
  StageBranching out;
  for_each_occupied(parent, [&](const std::array<int64_t, 3>& at) {
    std::array<std::vector<std::pair<int64_t, CellSpan>>, 3> axes;
    for (int d = 0; d < 3; ++d)
      axes[d] = d < l.dimension ? children_along(at[d], l.base, child.side, view.origin[d],
                                                 view.origin[d] + view.size[d])
                                : std::vector<std::pair<int64_t, CellSpan>>{{0, {0, 1}}};
    std::map<CellShape, std::pair<uint64_t, uint64_t>> classes;  // children, occupied
    for (const auto& [cz, sz] : axes[2])
      for (const auto& [cy, sy] : axes[1])
        for (const auto& [cx, sx] : axes[0]) {
          auto& cls = classes[CellShape{sx, sy, sz}];
          cls.first += 1;
          cls.second += child.occupied[child.at({cx, cy, cz})] ? 1 : 0;
        }
    ChildClasses kind;
    Occupied seen;
    for (const auto& [shape, counts] : classes) {
      kind.push_back({shape, counts.first});
      seen.push_back(counts.second);
      out.child_count += counts.second;
    }
    out.parents[kind][seen] += 1;
    out.parent_count += 1;
  });
  return out;
}

// One kind of parent at a given p: its children's chances r = p q per class.
struct KindAtP {
  std::vector<double> r;
  std::vector<uint64_t> n;
  double log_none = 0;            // log P(no child occupied)
  double mean = 0, variance = 0;  // of the occupied children, given at least one
};

KindAtP at_p(const std::vector<double>& q, const ChildClasses& kind, double p) {
  KindAtP k;
  double e0 = 0, v0 = 0;
  for (size_t g = 0; g < kind.size(); ++g) {
    const double r = std::min(1.0, p * q[g]);
    const auto n = static_cast<double>(kind[g].second);
    k.r.push_back(r);
    k.n.push_back(kind[g].second);
    k.log_none += r >= 1 ? -INFINITY : n * std::log1p(-r);
    e0 += n * r;
    v0 += n * r * (1 - r);
  }
  const double any = -std::expm1(k.log_none);
  k.mean = e0 / any;
  k.variance = std::max(0.0, (v0 + e0 * e0) / any - k.mean * k.mean);
  return k;
}

double times_log(double count, double x) { return count == 0 ? 0.0 : count * std::log(x); }

// A kind of parent as the likelihood reads it, hundreds of times a stage: flat arrays, in the
// order of the stage's maps, so that its sum is the same to the bit.
struct FlatKind {
  std::vector<double> q, n;      // per class: chance of keeping a final survivor, children
  std::vector<double> parents;   // per pattern of occupied children seen
  std::vector<double> occupied;  // per pattern, per class: the occupied children
};

// A stage's kinds of parent, and (flat, in the same order) the chance q of each child class
// keeping a final survivor.
struct Stage {
  StageBranching seen;
  std::vector<FlatKind> flat;
  size_t most_classes = 0;
  double split = 0.5;  // picture_split: where the interval of a coarse count splits its chance
};

// times_log(count, x) with log(x) given (count 0 adds nothing, whatever x).
double times_known_log(double count, double log_x) { return count == 0 ? 0.0 : count * log_x; }

double log_likelihood(const Stage& s, double p) {
  double sum = 0;
  // Per class: log r and log (1 - r), once a kind, not once a pattern.
  std::vector<double> logs(2 * s.most_classes);
  for (const FlatKind& k : s.flat) {
    const size_t classes = k.q.size();
    double log_none = 0;
    for (size_t g = 0; g < classes; ++g) {
      const double r = std::min(1.0, p * k.q[g]);
      log_none += r >= 1 ? -INFINITY : k.n[g] * std::log1p(-r);
      logs[2 * g] = std::log(r);
      logs[2 * g + 1] = std::log(1 - r);
    }
    const double log_any = std::log(-std::expm1(log_none));
    const double* occupied = k.occupied.data();
    for (const double parents : k.parents) {
      double l = -log_any;
      for (size_t g = 0; g < classes; ++g) {
        const double o = occupied[g];
        l += times_known_log(o, logs[2 * g]) + times_known_log(k.n[g] - o, logs[2 * g + 1]);
      }
      occupied += classes;
      sum += parents * l;
    }
  }
  return std::isnan(sum) ? -INFINITY : sum;
}

// The p in [kSmallest, 1] where the stage's likelihood is largest (it has one peak).
double most_likely(const Stage& s) {
  const double golden = (std::sqrt(5.0) - 1) / 2;
  double a = kSmallest, b = 1;
  double c = b - golden * (b - a), d = a + golden * (b - a);
  double fc = log_likelihood(s, c), fd = log_likelihood(s, d);
  for (int i = 0; i < 90; ++i) {
    if (fc < fd) {
      a = c, c = d, fc = fd;
      d = a + golden * (b - a), fd = log_likelihood(s, d);
    } else {
      b = d, d = c, fd = fc;
      c = b - golden * (b - a), fc = log_likelihood(s, c);
    }
  }
  double best = (a + b) / 2;
  for (const double edge : {kSmallest, 1.0})
    if (log_likelihood(s, edge) >= log_likelihood(s, best)) best = edge;
  return best;
}

// P(c occupied children), c = 0..m, of a kind: the convolution of its classes' binomials.
std::vector<double> count_distribution(const KindAtP& k) {
  std::vector<double> pmf{1.0};
  for (size_t g = 0; g < k.n.size(); ++g) {
    const uint64_t n = k.n[g];
    std::vector<double> binomial(n + 1);
    for (uint64_t j = 0; j <= n; ++j) {
      const double nj = static_cast<double>(j), nn = static_cast<double>(n);
      const double log_choose =
          std::lgamma(nn + 1) - std::lgamma(nj + 1) - std::lgamma(nn - nj + 1);
      binomial[j] = std::exp(log_choose + times_log(nj, k.r[g]) + times_log(nn - nj, 1 - k.r[g]));
    }
    std::vector<double> next(pmf.size() + n, 0.0);
    for (size_t a = 0; a < pmf.size(); ++a)
      for (uint64_t j = 0; j <= n; ++j) next[a + j] += pmf[a] * binomial[j];
    pmf = std::move(next);
  }
  return pmf;
}

struct Test {
  double chi_square = 0;
  int bins = 0, kinds = 0;
  double squares = 0, variance = 0;  // sum of (c - mean)^2 seen, and of the model's variance
};

// Pearson's statistic of the occupied children per parent, bins merged up to kLeastExpected
// expected: at most 4 children a parent (b = 2 in the plane) leave few bins, and merging up to
// the textbook 5 joined a half-plane's many 2-child parents with the 3-child ones, hiding them.
void add_test(Test& t, const KindAtP& k, const std::map<Occupied, uint64_t>& seen) {
  std::vector<double> observed(1, 0.0);
  double parents = 0;
  for (const auto& [occupied, count] : seen) {
    uint64_t c = 0;
    for (uint64_t o : occupied) c += o;
    if (observed.size() <= c) observed.resize(c + 1, 0.0);
    observed[c] += static_cast<double>(count);
    parents += static_cast<double>(count);
    t.squares += static_cast<double>(count) * (static_cast<double>(c) - k.mean) *
                 (static_cast<double>(c) - k.mean);
  }
  t.variance += parents * k.variance;
  uint64_t m = 0;
  for (uint64_t n : k.n) m += n;
  if (m > kMostChildrenTested) return;
  const std::vector<double> pmf = count_distribution(k);
  const double any = -std::expm1(k.log_none);
  observed.resize(pmf.size(), 0.0);
  std::vector<std::pair<double, double>> bins;  // observed, expected
  double o = 0, e = 0;
  for (size_t c = 1; c < pmf.size(); ++c) {
    o += observed[c];
    e += parents * pmf[c] / any;
    if (e >= kLeastExpected) bins.push_back({o, e}), o = 0, e = 0;
  }
  if (bins.empty()) return;  // too few parents expected in all: nothing to test
  bins.back().first += o, bins.back().second += e;
  for (const auto& [ob, ex] : bins) t.chi_square += (ob - ex) * (ob - ex) / ex;
  t.bins += static_cast<int>(bins.size());
  t.kinds += 1;
}

std::vector<Probability> as_probabilities(const std::vector<double>& p) {
  std::vector<Probability> out;
  for (double x : p) out.push_back(*Probability::from_double(std::clamp(x, 0.0, 1.0)));
  return out;
}

// Each child class's chance of keeping a final survivor, with the later stages' p.
void set_chances(const Lattice& l, int k, Stage& s, const std::vector<double>& p) {
  ExtinctionChance extinction(l, as_probabilities(p));
  s.flat.clear();
  s.most_classes = 0;
  for (const auto& [kind, seen] : s.seen.parents) {
    FlatKind flat;
    for (const auto& [shape, n] : kind) {
      flat.q.push_back(std::max(1e-300, 1 - extinction(k, shape)));
      flat.n.push_back(static_cast<double>(n));
    }
    for (const auto& [occupied, parents] : seen) {
      flat.parents.push_back(static_cast<double>(parents));
      for (uint64_t o : occupied) flat.occupied.push_back(static_cast<double>(o));
    }
    s.most_classes = std::max(s.most_classes, kind.size());
    s.flat.push_back(std::move(flat));
  }
}

// The mean of p under the stage's likelihood with a flat prior: unlike the most likely p it never
// sits at 0 when a stage's few parents each have one child.
double posterior_mean(const Stage& s) {
  constexpr int kSteps = 400;
  std::vector<double> l(kSteps);
  double top = -INFINITY;
  for (int i = 0; i < kSteps; ++i)
    top = std::max(top, l[i] = log_likelihood(s, (i + 0.5) / kSteps));
  double mass = 0, moment = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double w = std::exp(l[i] - top);
    mass += w, moment += w * (i + 0.5) / kSteps;
  }
  return moment / mass;
}

// Where the likelihood falls to `level` between `inside` (above it) and `outside`.
double crossing(const Stage& s, double inside, double outside, double level) {
  for (int i = 0; i < 60; ++i) {
    const double mid = (inside + outside) / 2;
    (log_likelihood(s, mid) >= level ? inside : outside) = mid;
  }
  return (inside + outside) / 2;
}

// The distribution of the stage's occupied children in all, at p: each parent's count given
// that it is occupied, convolved over the parents.
std::vector<double> stage_count_distribution(const Stage& s, double p) {
  std::vector<double> total{1.0};
  size_t i = 0;
  for (const auto& [kind, seen] : s.seen.parents) {
    const KindAtP k = at_p(s.flat[i++].q, kind, p);
    std::vector<double> one = count_distribution(k);
    const double any = -std::expm1(k.log_none);
    one[0] = 0;
    for (double& x : one) x /= any;
    uint64_t parents = 0;
    for (const auto& entry : seen) parents += entry.second;
    for (uint64_t j = 0; j < parents; ++j) {
      std::vector<double> next(total.size() + one.size() - 1, 0.0);
      for (size_t a = 0; a < total.size(); ++a)
        if (total[a] > 0)
          for (size_t c = 1; c < one.size(); ++c) next[a + c] += total[a] * one[c];
      total = std::move(next);
    }
  }
  return total;
}

// The chance of fewer occupied children than seen plus `split` of the chance of as many: with
// split uniform, its value at the true p is uniform too, so cutting 2.5 % off each end covers
// exactly 95 % however coarse the count.
double split_tail(const Stage& s, double p) {
  const std::vector<double> pmf = stage_count_distribution(s, p);
  const auto t = static_cast<size_t>(s.seen.child_count);
  double below = 0;
  for (size_t c = 0; c < std::min(t, pmf.size()); ++c) below += pmf[c];
  return below + (t < pmf.size() ? s.split * pmf[t] : 0.0);
}

// Where `falling` (decreasing in p) crosses `level` in [kSmallest, 1].
template <class Falling>
double falls_to(Falling falling, double level) {
  double lo = kSmallest, hi = 1;
  for (int i = 0; i < 50; ++i) {
    const double mid = (lo + hi) / 2;
    (falling(mid) >= level ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

// The children in view of all the stage's occupied parents.
uint64_t possible_children(const Stage& s) {
  uint64_t n = 0;
  for (const auto& [kind, seen] : s.seen.parents) {
    uint64_t m = 0, parents = 0;
    for (const auto& cls : kind) m += cls.second;
    for (const auto& entry : seen) parents += entry.second;
    n += m * parents;
  }
  return n;
}

// Where the likelihood ratio stays inside the chi-square point: right when the count is large.
void set_likelihood_interval(const Stage& s, StageFit& f) {
  const double level = log_likelihood(s, f.probability) - kInterval95 / 2;
  f.low =
      log_likelihood(s, kSmallest) >= level ? 0.0 : crossing(s, f.probability, kSmallest, level);
  f.high = log_likelihood(s, 1.0) >= level ? 1.0 : crossing(s, f.probability, 1.0, level);
}

// For a coarse count (a few parents: a lone root, a window's cut corner) no interval that is a
// function of the count alone holds 95 % at every p (at p = 0.7 one root's 4 children give 91 %
// or 100 %), and the likelihood ratio's is too short where the fit is 0 or 1. The split count's
// interval holds exactly 95 %; it always holds the fitted p too.
void set_split_interval(const Stage& s, StageFit& f) {
  auto tail = [&](double x) { return split_tail(s, x); };
  f.low = std::min(f.probability, tail(kSmallest) <= 0.975 ? 0.0 : falls_to(tail, 0.975));
  f.high = std::max(f.probability, tail(1.0) >= 0.025 ? 1.0 : falls_to(tail, 0.025));
}

// The stage's p with its interval, expected branching and test, given the later stages' p.
StageFit fit_stage(const Lattice& l, int k, Stage& s, std::vector<double>& p) {
  set_chances(l, k, s, p);
  StageFit f;
  f.stage = k;
  f.measured = s.seen.child_count;
  f.parents = s.seen.parent_count;
  f.probability = most_likely(s);
  const uint64_t children = possible_children(s);
  if (children == f.parents) {
    f.low = 0, f.high = 1;  // one child in view a parent: its count cannot vary with p
  } else if (children <= kFewChildren) {
    set_split_interval(s, f);
  } else {
    set_likelihood_interval(s, f);
  }
  // The earlier stages' extinction chances take the mean p under the likelihood: the most likely
  // p is 0 when a stage's few parents have one child each, and would make every earlier child die.
  p[static_cast<size_t>(k - 1)] = posterior_mean(s);

  Test t;
  size_t i = 0;
  for (const auto& [kind, seen] : s.seen.parents)
    add_test(t, at_p(s.flat[i++].q, kind, f.probability), seen);
  f.chi_square = t.chi_square;
  f.degrees = std::max(0, t.bins - t.kinds - 1);
  f.p_value = f.degrees > 0 ? chi_square_tail(f.chi_square, f.degrees) : 1.0;
  f.dispersion = t.squares < t.variance ? -1 : 1;
  return f;
}

// FNV-1a over the occupied cells' indices: the picture's own seed for its splits.
uint64_t picture_hash(const std::vector<bool>& cells) {
  uint64_t h = 1469598103934665603ull;
  for (size_t i = 0; i < cells.size(); ++i)
    if (cells[i]) h = (h ^ i) * 1099511628211ull;
  return h;
}

// A number in [0, 1) drawn from the picture itself (its hash `h`) for stage k, spread evenly over
// pictures: so the split count's interval is random only as the picture is, and one picture
// always gives one interval.
double picture_split(uint64_t h, int k) {
  uint64_t z = h + 0x9e3779b97f4a7c15ull * static_cast<uint64_t>(k);  // splitmix64's finaliser
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

// The mean and variance of the occupied children of a stage's parents, as fitted.
std::pair<double, double> branching_moments(const Stage& s, double p) {
  double mean = 0, variance = 0, parents = 0;
  size_t i = 0;
  for (const auto& [kind, seen] : s.seen.parents) {
    const KindAtP k = at_p(s.flat[i++].q, kind, p);
    double n = 0;
    for (const auto& entry : seen) n += static_cast<double>(entry.second);
    mean += n * k.mean, variance += n * k.variance, parents += n;
  }
  return parents > 0 ? std::pair{mean / parents, variance / parents} : std::pair{0.0, 0.0};
}

}  // namespace

std::vector<uint64_t> occupied_cells(const Lattice& l, const Box& view,
                                     const std::vector<bool>& cells) {
  std::vector<uint64_t> counts(static_cast<size_t>(l.stages + 1), 0);
  // Level j of the pyramid is stage K - j.
  for_each_box_level(l.base, l.dimension, view, cells, l.stages, [&](const BoxLevel& level) {
    counts[static_cast<size_t>(l.stages - level.index)] =
        static_cast<uint64_t>(std::count(level.occupied.begin(), level.occupied.end(), true));
  });
  return counts;
}

CurdFit fit_curd(const Lattice& l, const Box& view, const std::vector<bool>& cells) {
  const int K = l.stages;
  std::vector<BoxLevel> levels;  // level j: stage K - j
  for_each_box_level(l.base, l.dimension, view, cells, K,
                     [&](const BoxLevel& level) { levels.push_back(level); });
  std::vector<Stage> stages(static_cast<size_t>(K + 1));
  for (int k = 1; k <= K; ++k)
    stages[k].seen = branching(l, view, levels[static_cast<size_t>(K - k + 1)],
                               levels[static_cast<size_t>(K - k)]);
  const uint64_t hash = picture_hash(cells);
  for (int k = 1; k <= K; ++k) stages[k].split = picture_split(hash, k);
  std::vector<double> p(static_cast<size_t>(K), 1.0);
  CurdFit fit;
  fit.stages.resize(static_cast<size_t>(K));
  for (int k = K; k >= 1; --k)
    fit.stages[static_cast<size_t>(k - 1)] = fit_stage(l, k, stages[k], p);
  // Expected counts from the occupied roots: a branching chain, E and Var stage by stage.
  double mean = static_cast<double>(
      std::count(levels.back().occupied.begin(), levels.back().occupied.end(), true));
  double variance = 0;
  for (int k = 1; k <= K; ++k) {
    StageFit& f = fit.stages[static_cast<size_t>(k - 1)];
    const auto [mu, sigma2] = branching_moments(stages[k], f.probability);
    variance = mean * sigma2 + variance * mu * mu;
    mean *= mu;
    f.expected = mean;
    f.expected_sd = std::sqrt(variance);
    f.z = f.expected_sd > 0 ? (static_cast<double>(f.measured) - mean) / f.expected_sd : 0.0;
    fit.chi_square += f.chi_square;
    fit.degrees += f.degrees;
  }
  fit.p_value = fit.degrees > 0 ? chi_square_tail(fit.chi_square, fit.degrees) : 1.0;
  return fit;
}

}  // namespace curdle
