#include "curdle/markov_report.h"

#include <bit>
#include <cmath>
#include <span>

#include "curdle/markov_theory.h"
#include "curdle/theory.h"

namespace curdle {
namespace {

// The cells of stage k in each state: counted a word at a time from the planes.
std::vector<uint64_t> state_counts(std::span<const Curd> planes, int k, size_t states) {
  std::vector<uint64_t> counts(states, 0);
  const Bitset& first = planes[0].stages[static_cast<size_t>(k)];
  const size_t words = first.words.size();
  for (size_t w = 0; w < words; ++w) {
    uint64_t any = 0;
    for (const Curd& p : planes) any |= p.stages[static_cast<size_t>(k)].words[w];
    for (size_t s = 1; s < states; ++s) {
      uint64_t m = any;
      for (size_t p = 0; p < planes.size(); ++p) {
        const uint64_t bits = planes[p].stages[static_cast<size_t>(k)].words[w];
        m &= (s >> p & 1) ? bits : ~bits;
      }
      counts[s] += static_cast<uint64_t>(std::popcount(m));
    }
  }
  return counts;
}

// Levels 0..K: the stage-m cells with a finest descendant in a state of `targets`.
std::vector<uint64_t> set_box_counts(std::span<const Curd> planes, int K, uint64_t B,
                                     const std::vector<bool>& targets) {
  const Bitset& finest0 = planes[0].stages[static_cast<size_t>(K)];
  Bitset level;
  level.assign_zero(finest0.size);
  for (size_t w = 0; w < finest0.words.size(); ++w) {
    uint64_t in = 0;
    for (size_t s = 1; s < targets.size(); ++s) {
      if (!targets[s]) continue;
      uint64_t m = ~uint64_t{0};
      for (size_t p = 0; p < planes.size(); ++p) {
        const uint64_t bits = planes[p].stages[static_cast<size_t>(K)].words[w];
        m &= (s >> p & 1) ? bits : ~bits;
      }
      in |= m;
    }
    level.words[w] = in;
  }
  if (finest0.size % 64)
    level.words[finest0.words.size() - 1] &= (uint64_t{1} << (finest0.size % 64)) - 1;
  std::vector<uint64_t> counts(static_cast<size_t>(K) + 1);
  counts[static_cast<size_t>(K)] = level.count();
  for (int m = K - 1; m >= 0; --m) {
    Bitset up;
    up.assign_zero(planes[0].stages[static_cast<size_t>(m)].size);
    for_each_set(level, 0, level.size, [&](uint64_t i) { up.set(i / B); });
    counts[static_cast<size_t>(m)] = up.count();
    level = std::move(up);
  }
  return counts;
}

}  // namespace

MarkovReport make_markov_report(const Design& design, const CurdGroup& group,
                                const CurdField& field, const Box& view) {
  const Lattice& l = design.lattice;
  const MarkovChain& chain = *group.chain;
  const std::span<const Curd> planes(field.curds.data() + group.first,
                                     static_cast<size_t>(group.planes));
  const size_t n = chain.living() + 1;
  MarkovReport r;
  r.name = design.curds[group.first].name;
  r.states = chain.states;
  r.stationary = chain.stationary();
  for (int k = 1; k <= l.stages; ++k) r.wheys |= chain.revives(k);
  const bool quota = l.mode == Mode::quota;
  r.sd_is_approximate = quota && !(view == design.field);
  for (int k = 0; k <= l.stages; ++k) {
    const std::vector<uint64_t> counts = state_counts(planes, k, n);
    const std::vector<double> share = state_shares(chain, k);
    const std::vector<double> sd = state_count_sd(l, chain, k, view);
    const uint64_t cells = cells_meeting(l, k, view);
    uint64_t living = 0;
    for (size_t s = 1; s < n; ++s) living += counts[s];
    for (size_t s = 0; s < n; ++s) {
      StateStageRow row;
      row.stage = k;
      row.state = chain.state_name(static_cast<uint32_t>(s));
      row.cells = cells;
      row.count = s == 0 ? cells - living : counts[s];
      row.share = share[s];
      row.expected = static_cast<double>(cells) * share[s];
      row.expected_sd = quota && !r.sd_is_approximate && k > 0 ? 0.0 : sd[s];
      if (row.expected_sd > 0)
        row.z = (static_cast<double>(row.count) - row.expected) / row.expected_sd;
      r.stages.push_back(row);
    }
  }
  auto add_set = [&](const std::string& name, const std::vector<bool>& targets) {
    StateSet set;
    set.name = name;
    set.box_counts = set_box_counts(planes, l.stages, l.children(), targets);
    set.expected_box_counts = expected_state_box_counts(l, chain, targets, view);
    set.fit = fit_box_dimension(set.box_counts, l.base);
    set.expected_fit = fit_box_dimension(set.expected_box_counts, l.base);
    set.theory_dimension = stationary_dimension(l, chain, targets);
    set.extinction = extinction_chance(l, chain, targets);
    r.sets.push_back(std::move(set));
  };
  for (size_t s = 1; s < n; ++s) {
    std::vector<bool> one(n, false);
    one[s] = true;
    add_set(chain.states[s - 1], one);
  }
  std::vector<bool> living(n, true);
  living[0] = false;
  add_set("living", living);
  return r;
}

}  // namespace curdle
