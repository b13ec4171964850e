#include "curdle/state_tree.h"

#include <algorithm>
#include <cmath>

#include "curdle/check.h"

namespace curdle {
namespace {

// A product of many children's messages is rescaled before it can underflow.
constexpr double kRescaleBelow = 1e-150;

}  // namespace

StateTree::StateTree(const Lattice& l, const Box& view, std::vector<uint8_t> leaves, size_t states)
    : states_(states), leaves_(std::move(leaves)) {
  const int K = l.stages;
  std::vector<std::array<int64_t, 3>> first(static_cast<size_t>(K) + 1), count(first.size());
  for (int k = 0; k <= K; ++k) {
    const auto side = static_cast<int64_t>(l.side_in_cells(k));
    uint64_t n = 1;
    for (int d = 0; d < 3; ++d) {
      auto& f = first[static_cast<size_t>(k)][d];
      auto& c = count[static_cast<size_t>(k)][d];
      if (d >= l.dimension) {
        f = 0, c = 1;
        continue;
      }
      f = floor_div(view.origin[d], side);
      c = floor_div(view.origin[d] + view.size[d] - 1, side) - f + 1;
      n *= static_cast<uint64_t>(c);
    }
    nodes_.push_back(n);
  }
  CHECK(nodes_.back() == leaves_.size(), "one state per finest cell of the view");
  parent_.resize(static_cast<size_t>(K) + 1);
  for (int k = 1; k <= K; ++k) {
    const auto& f = first[static_cast<size_t>(k)];
    const auto& c = count[static_cast<size_t>(k)];
    const auto& pf = first[static_cast<size_t>(k) - 1];
    const auto& pc = count[static_cast<size_t>(k) - 1];
    auto& parents = parent_[static_cast<size_t>(k)];
    parents.reserve(nodes_[static_cast<size_t>(k)]);
    for (int64_t z = 0; z < c[2]; ++z)
      for (int64_t y = 0; y < c[1]; ++y)
        for (int64_t x = 0; x < c[0]; ++x) {
          const int64_t b = l.dimension >= 1 ? l.base : 1;
          const int64_t px = floor_div(f[0] + x, b) - pf[0];
          const int64_t py = l.dimension >= 2 ? floor_div(f[1] + y, b) - pf[1] : 0;
          const int64_t pz = l.dimension >= 3 ? floor_div(f[2] + z, b) - pf[2] : 0;
          parents.push_back(static_cast<uint32_t>((pz * pc[1] + py) * pc[0] + px));
        }
  }
  for (const uint8_t s : leaves_) CHECK(s < states_, "a leaf's state is one of the chain's");
}

StateTreeCounts StateTree::expected_counts(const ChainValues& chain) const {
  const size_t S = states_;
  const int K = stages();
  StateTreeCounts out;
  out.roots.assign(S, 0.0);
  out.steps.assign(static_cast<size_t>(K),
                   std::vector<std::vector<double>>(S, std::vector<double>(S, 0.0)));
  // beta[k][node * S + i]: the chance of the leaves below a stage-k cell in state i, scaled.
  std::vector<std::vector<double>> beta(static_cast<size_t>(K));
  double log_scale = 0;
  std::vector<double> message(S);
  for (int k = K - 1; k >= 0; --k) {
    auto& up = beta[static_cast<size_t>(k)];
    up.assign(nodes_[static_cast<size_t>(k)] * S, 1.0);
    const auto& P = chain.transitions[static_cast<size_t>(k)];
    const auto& parents = parent_[static_cast<size_t>(k) + 1];
    for (size_t c = 0; c < parents.size(); ++c) {
      double* b = up.data() + size_t{parents[c]} * S;
      for (size_t i = 0; i < S; ++i) {
        if (k + 1 == K) {
          message[i] = P[i][leaves_[c]];
        } else {
          const double* below = beta[static_cast<size_t>(k) + 1].data() + c * S;
          double m = 0;
          for (size_t j = 0; j < S; ++j) m += P[i][j] * below[j];
          message[i] = m;
        }
      }
      double largest = 0;
      for (size_t i = 0; i < S; ++i) largest = std::max(largest, b[i] *= message[i]);
      if (largest > 0 && largest < kRescaleBelow) {
        for (size_t i = 0; i < S; ++i) b[i] /= largest;
        log_scale += std::log(largest);
      }
    }
    for (size_t n = 0; n < nodes_[static_cast<size_t>(k)]; ++n) {
      double* b = up.data() + n * S;
      const double largest = *std::max_element(b, b + S);
      if (largest <= 0) {
        out.log_likelihood = -INFINITY;  // the chain cannot make these leaves
        return out;
      }
      for (size_t i = 0; i < S; ++i) b[i] /= largest;
      log_scale += std::log(largest);
    }
  }
  // Down: gamma, each cell's state given every leaf; each step's share of it.
  std::vector<double> gamma(nodes_[0] * S), below;
  out.log_likelihood = log_scale;
  out.root_leaves = beta[0];
  for (size_t r = 0; r < nodes_[0]; ++r) {
    double z = 0;
    for (size_t i = 0; i < S; ++i) z += gamma[r * S + i] = chain.start[i] * beta[0][r * S + i];
    if (z <= 0) {
      out.log_likelihood = -INFINITY;
      return out;
    }
    out.log_likelihood += std::log(z);
    for (size_t i = 0; i < S; ++i) out.roots[i] += gamma[r * S + i] /= z;
  }
  for (int k = 1; k <= K; ++k) {
    const auto& P = chain.transitions[static_cast<size_t>(k) - 1];
    const auto& parents = parent_[static_cast<size_t>(k)];
    auto& steps = out.steps[static_cast<size_t>(k) - 1];
    const bool leaf = k == K;
    if (!leaf) below.assign(nodes_[static_cast<size_t>(k)] * S, 0.0);
    for (size_t c = 0; c < parents.size(); ++c) {
      const double* g = gamma.data() + size_t{parents[c]} * S;
      const double* b = leaf ? nullptr : beta[static_cast<size_t>(k)].data() + c * S;
      for (size_t i = 0; i < S; ++i) {
        if (g[i] == 0) continue;
        if (leaf) {
          steps[i][leaves_[c]] += g[i];
          continue;
        }
        double m = 0;
        for (size_t j = 0; j < S; ++j) m += P[i][j] * b[j];
        if (m <= 0) continue;
        const double w = g[i] / m;
        for (size_t j = 0; j < S; ++j) {
          const double xi = w * P[i][j] * b[j];
          steps[i][j] += xi;
          below[c * S + j] += xi;
        }
      }
    }
    if (!leaf) gamma.swap(below);
  }
  return out;
}

}  // namespace curdle
