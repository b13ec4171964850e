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

// A curd for box counting a set of states (boxcount.h): its coarser stages hold every cell that
// can have a descendant in the set (the living cells where dead is absorbing, every cell where
// it is not); set_finest puts the set in its finest stage.
Curd set_curd(std::span<const Curd> planes, int K, bool wheys) {
  Curd set;
  set.stages.resize(static_cast<size_t>(K) + 1);
  for (int k = 0; k < K; ++k) {
    const Bitset& first = planes[0].stages[static_cast<size_t>(k)];
    Bitset& out = set.stages[static_cast<size_t>(k)];
    out.assign_zero(first.size);
    for (size_t w = 0; w < first.words.size(); ++w) {
      uint64_t in = wheys ? ~uint64_t{0} : 0;
      if (!wheys)
        for (const Curd& p : planes) in |= p.stages[static_cast<size_t>(k)].words[w];
      out.words[w] = in;
    }
    if (first.size % 64)
      out.words[first.words.size() - 1] &= (uint64_t{1} << (first.size % 64)) - 1;
  }
  set.stages[static_cast<size_t>(K)].assign_zero(planes[0].stages[static_cast<size_t>(K)].size);
  return set;
}

void set_finest(Curd& set, std::span<const Curd> planes, const std::vector<bool>& targets) {
  const size_t K = set.stages.size() - 1;
  Bitset& out = set.stages[K];
  for (size_t w = 0; w < out.words.size(); ++w) {
    uint64_t in = 0;
    for (size_t s = 1; s < targets.size(); ++s) {
      if (!targets[s]) continue;
      uint64_t m = ~uint64_t{0};
      for (size_t p = 0; p < planes.size(); ++p) {
        const uint64_t bits = planes[p].stages[K].words[w];
        m &= (s >> p & 1) ? bits : ~bits;
      }
      in |= m;
    }
    out.words[w] = in;
  }
  if (out.size % 64) out.words[out.words.size() - 1] &= (uint64_t{1} << (out.size % 64)) - 1;
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
  Curd counted = set_curd(planes, l.stages, r.wheys);
  std::vector<Bitset> scratch;
  auto add_set = [&](const std::string& name, const std::vector<bool>& targets) {
    StateSet set;
    set.name = name;
    set_finest(counted, planes, targets);
    set.box_counts = box_counts(counted, l.children(), scratch);
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
