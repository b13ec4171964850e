#include "curdle/theory.h"

#include <cmath>

namespace curdle {
namespace {

// Along one axis: the stage-k columns meeting [o, o + s), grouped by their stage-j ancestor;
// returns the sum over ancestors of (columns under it)^2.
double axis_sum_of_squares(const Lattice& l, int k, int j, int64_t o, int64_t s) {
  const int64_t width = static_cast<int64_t>(l.side_in_cells(k));
  const int64_t first = floor_div(o, width), last = floor_div(o + s - 1, width);
  int64_t group = 1;
  for (int i = j; i < k; ++i) group *= l.base;
  double sum = 0;
  for (int64_t a = floor_div(first, group); a <= floor_div(last, group); ++a) {
    const int64_t lo = std::max(first, a * group), hi = std::min(last, a * group + group - 1);
    const double n = static_cast<double>(hi - lo + 1);
    sum += n * n;
  }
  return sum;
}

}  // namespace

double sum_of_squares(const Lattice& l, int k, int j, const Box& box) {
  double t = 1;
  for (int d = 0; d < l.dimension; ++d)
    t *= axis_sum_of_squares(l, k, j, box.origin[d], box.size[d]);
  return t;
}

uint64_t cells_meeting(const Lattice& l, int stage, const Box& box) {
  const int64_t width = static_cast<int64_t>(l.side_in_cells(stage));
  uint64_t n = 1;
  for (int d = 0; d < l.dimension; ++d) {
    const int64_t first = floor_div(box.origin[d], width);
    const int64_t last = floor_div(box.origin[d] + box.size[d] - 1, width);
    n *= static_cast<uint64_t>(last - first + 1);
  }
  return n;
}

double survival_probability(const std::vector<Probability>& p, int stage) {
  double P = 1;
  for (int i = 0; i < stage; ++i) P *= p[i].value();
  return P;
}

double expected_survivors(const Lattice& l, const std::vector<Probability>& p, int stage,
                          const Box& box) {
  return static_cast<double>(cells_meeting(l, stage, box)) * survival_probability(p, stage);
}

double survivors_sd(const Lattice& l, const std::vector<Probability>& p, int k, const Box& box) {
  const double B = static_cast<double>(l.children());
  const double C = static_cast<double>(cells_meeting(l, k, box));
  const double Pk = survival_probability(p, k);
  double var = C * Pk * (1 - Pk);
  std::vector<double> T(k + 1);
  for (int j = 0; j <= k; ++j) T[j] = sum_of_squares(l, k, j, box);
  for (int j = 0; j < k; ++j) {
    const double pi = p[j].value();  // stage j + 1
    const double r = l.mode == Mode::exact ? (B > 1 ? pi * (pi * B - 1) / (B - 1) : pi) : pi * pi;
    double Q = 1;
    for (int i = j + 1; i < k; ++i) Q *= p[i].value();
    const double Pj = survival_probability(p, j);
    var += (T[j] - T[j + 1]) * (Pj * r * Q * Q - Pk * Pk);
  }
  return var > 0 ? std::sqrt(var) : 0.0;
}

double theory_dimension(const Lattice& l, double p) {
  return l.dimension + std::log(p) / std::log(static_cast<double>(l.base));
}

}  // namespace curdle
