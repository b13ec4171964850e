#include "curdle/fit.h"

#include <algorithm>
#include <cmath>

#include "curdle/box_levels.h"
#include "curdle/extinction.h"
#include "curdle/theory.h"

namespace curdle {

std::vector<uint64_t> occupied_cells(const Lattice& l, const Box& field,
                                     const std::vector<bool>& cells) {
  std::vector<uint64_t> counts(static_cast<size_t>(l.stages + 1), 0);
  // Level j of the pyramid is stage K - j.
  for_each_box_level(
      l.base, l.dimension, Box{{0, 0, 0}, field.size}, cells, l.stages, [&](const BoxLevel& level) {
        counts[static_cast<size_t>(l.stages - level.index)] =
            static_cast<uint64_t>(std::count(level.occupied.begin(), level.occupied.end(), true));
      });
  return counts;
}

std::vector<StageFit> fit_probabilities(const Lattice& l, const Box& field,
                                        const std::vector<uint64_t>& measured) {
  const int K = l.stages;
  const Box at_corner{{0, 0, 0}, field.size};
  // Candidates of stage k: the occupied cells of stage k - 1 times their children in the field.
  std::vector<double> candidates(static_cast<size_t>(K + 1), 0.0);
  std::vector<double> p(static_cast<size_t>(K), 1.0);
  for (int k = 1; k <= K; ++k) {
    const double children = static_cast<double>(cells_meeting(l, k, at_corner)) /
                            static_cast<double>(cells_meeting(l, k - 1, at_corner));
    candidates[k] = static_cast<double>(measured[k - 1]) * children;
    p[k - 1] = candidates[k] > 0 ? static_cast<double>(measured[k]) / candidates[k] : 0.0;
  }
  // Correct the ratios for extinction: p_k moves by how far the expectations miss.
  auto as_probabilities = [&] {
    std::vector<Probability> out;
    for (double x : p) out.push_back(*Probability::from_double(std::clamp(x, 0.0, 1.0)));
    return out;
  };
  for (int round = 0; round < 200; ++round) {
    const std::vector<double> e = expected_box_counts(l, as_probabilities(), at_corner);
    double worst = 0;
    for (int k = 1; k <= K; ++k) {
      if (measured[k] == 0 || e[k] <= 0 || e[k - 1] <= 0) continue;
      const double miss = (static_cast<double>(measured[k]) / e[k]) /
                          (static_cast<double>(measured[k - 1]) / e[k - 1]);
      worst = std::max(worst, std::fabs(miss - 1));
      p[k - 1] = std::clamp(p[k - 1] * miss, 1e-9, 1.0);
    }
    if (worst < 1e-10) break;
  }
  const std::vector<double> e = expected_box_counts(l, as_probabilities(), at_corner);
  std::vector<StageFit> out;
  for (int k = 1; k <= K; ++k) {
    StageFit s;
    s.stage = k;
    s.probability = std::clamp(p[k - 1], 0.0, 1.0);
    s.sd = candidates[k] > 0 ? std::sqrt(s.probability * (1 - s.probability) / candidates[k]) : 0;
    s.measured = measured[k];
    s.expected = e[k];
    out.push_back(s);
  }
  return out;
}

}  // namespace curdle
