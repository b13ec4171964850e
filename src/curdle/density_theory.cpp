#include "curdle/density_theory.h"

#include <algorithm>
#include <cmath>

#include "curdle/cell_index.h"
#include "curdle/theory.h"

namespace curdle {
namespace {

class Walk {
 public:
  Walk(const Lattice& l, const std::vector<Probability>& p, const DensityField& f, const Box& view)
      : l_(l), f_(f), view_(view), K_(l.stages) {
    const auto n = static_cast<size_t>(K_ + 1);
    for (int k = 0; k <= K_; ++k) product_.push_back(survival_probability(p, k));
    sums_.assign(n, std::vector<double>(n));
    squares_.assign(n, std::vector<double>(n));
    child_.assign(n, std::vector<double>(n));
    result_.survivors.assign(n, 0);
    variance_.assign(n, 0);
    result_.box_counts.assign(n, 0);
  }

  DensityExpectation run() {
    const auto side = static_cast<int64_t>(l_.side_in_cells(0));
    std::array<int64_t, 3> lo{0, 0, 0}, hi{0, 0, 0};
    for (int d = 0; d < l_.dimension; ++d) {
      lo[d] = floor_div(view_.origin[d], side);
      hi[d] = floor_div(view_.origin[d] + view_.size[d] - 1, side);
    }
    std::vector<double> ignored(static_cast<size_t>(K_ + 1));
    for (int64_t z = lo[2]; z <= hi[2]; ++z)
      for (int64_t y = lo[1]; y <= hi[1]; ++y)
        for (int64_t x = lo[0]; x <= hi[0]; ++x) visit(0, {x, y, z}, 1.0, ignored);
    result_.survivors_sd.resize(variance_.size());
    for (size_t k = 0; k < variance_.size(); ++k)
      result_.survivors_sd[k] = std::sqrt(std::max(0.0, variance_[k]));
    return result_;
  }

 private:
  // Adds the stage-j cell c (alive with probability S) to the sums; `up` receives T_k of its
  // subtree for k >= j. Returns h, the chance it keeps a final survivor in the view if alive.
  double visit(int j, const std::array<int64_t, 3>& c, double S, std::vector<double>& up) {
    const auto J = static_cast<size_t>(j);
    result_.survivors[J] += S;
    variance_[J] += S * (1 - S);
    up[J] += S;
    if (j == K_) {
      result_.box_counts[J] += S;
      return 1;
    }
    std::vector<double>& sums = sums_[J];
    std::vector<double>& squares = squares_[J];
    std::vector<double>& child = child_[J];
    std::fill(sums.begin(), sums.end(), 0.0);
    std::fill(squares.begin(), squares.end(), 0.0);
    // The children meeting the view, along each axis.
    const auto side = static_cast<int64_t>(l_.side_in_cells(j + 1));
    std::array<int64_t, 3> lo{0, 0, 0}, hi{0, 0, 0};
    for (int d = 0; d < l_.dimension; ++d) {
      lo[d] = std::max(c[d] * l_.base, floor_div(view_.origin[d], side));
      hi[d] = std::min(c[d] * l_.base + l_.base - 1,
                       floor_div(view_.origin[d] + view_.size[d] - 1, side));
    }
    double none = 1;  // the chance that no child keeps a final survivor
    for (int64_t z = lo[2]; z <= hi[2]; ++z)
      for (int64_t y = lo[1]; y <= hi[1]; ++y)
        for (int64_t x = lo[0]; x <= hi[0]; ++x) {
          const std::array<int64_t, 3> a{x, y, z};
          const double Sa = f_.survival(l_, j + 1, a, product_[J + 1]);
          if (!(Sa > 0)) continue;
          std::fill(child.begin() + j + 1, child.end(), 0.0);
          const double h = visit(j + 1, a, Sa, child);
          for (size_t k = J + 1; k < child.size(); ++k) {
            sums[k] += child[k];
            squares[k] += child[k] * child[k];
          }
          none *= 1 - std::min(1.0, Sa / S) * h;
        }
    for (size_t k = J + 1; k < sums.size(); ++k) {
      variance_[k] += (1 / S - 1) * (sums[k] * sums[k] - squares[k]);
      up[k] += sums[k];
    }
    result_.box_counts[J] += S * (1 - none);
    return 1 - none;
  }

  const Lattice& l_;
  const DensityField& f_;
  const Box& view_;
  int K_;
  std::vector<double> product_;  // P_k
  // Per depth j: the sums and squared sums of the children's T_k, and one child's T_k.
  std::vector<std::vector<double>> sums_, squares_, child_;
  std::vector<double> variance_;
  DensityExpectation result_;
};

}  // namespace

DensityExpectation expect_with_density(const Lattice& lattice, const std::vector<Probability>& p,
                                       const DensityField& field, const Box& view) {
  return Walk(lattice, p, field, view).run();
}

}  // namespace curdle
