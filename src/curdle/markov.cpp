#include "curdle/markov.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace curdle {

int MarkovChain::planes() const { return std::max(1, static_cast<int>(std::bit_width(living()))); }

bool MarkovChain::revives(int stage) const {
  const auto& dead = row(stage, 0);
  for (size_t j = 1; j < dead.size(); ++j)
    if (dead[j].value() > 0) return true;
  return false;
}

bool MarkovChain::stationary() const {
  for (const auto& m : transitions)
    for (size_t i = 0; i < m.size(); ++i)
      for (size_t j = 0; j < m[i].size(); ++j)
        if (m[i][j].value() != transitions[0][i][j].value()) return false;
  return true;
}

std::string MarkovChain::state_name(uint32_t state) const {
  if (state == 0) return "dead";
  return state <= living() ? states[state - 1] : "state " + std::to_string(state);
}

Probability probability_sum(const std::vector<Probability>& terms, size_t n) {
  if (const auto sum = exact_sum(terms, n)) {
    if (sum->first >= sum->second) return Probability::fraction(1, 1);
    return Probability::fraction(sum->first, sum->second);
  }
  double sum = 0;
  for (size_t i = 0; i < n; ++i) sum += terms[i].value();
  return *Probability::from_double(std::min(1.0, sum));
}

uint32_t StateBounds::state_of(uint64_t u) const {
  for (size_t j = 0; j < bound.size(); ++j)
    if (whole[j] || u < bound[j]) return static_cast<uint32_t>(j + 1);
  return 0;
}

StateBounds state_bounds(const std::vector<Probability>& row) {
  StateBounds b;
  std::vector<Probability> living(row.begin() + 1, row.end());
  for (size_t j = 1; j <= living.size(); ++j) {
    const Probability T = probability_sum(living, j);
    b.bound.push_back(T.threshold());
    b.whole.push_back(T.certain());
  }
  return b;
}

std::vector<CurdGroup> curd_groups(const std::vector<CurdSpec>& curds) {
  std::vector<CurdGroup> groups;
  for (size_t c = 0; c < curds.size();) {
    CurdGroup g;
    g.first = c;
    g.chain = curds[c].chain.get();
    g.planes = g.chain ? g.chain->planes() : 1;
    groups.push_back(g);
    c += static_cast<size_t>(g.planes);
  }
  return groups;
}

std::vector<CurdMember> curd_members(const std::vector<CurdSpec>& curds) {
  std::vector<CurdMember> members;
  const std::vector<CurdGroup> groups = curd_groups(curds);
  for (size_t g = 0; g < groups.size(); ++g) {
    if (!groups[g].chain) {
      members.push_back({curds[groups[g].first].name, g, 1});
      continue;
    }
    for (uint32_t s = 1; s <= groups[g].chain->living(); ++s)
      members.push_back({groups[g].chain->state_name(s), g, s});
  }
  return members;
}

std::vector<size_t> members_of(const std::vector<CurdSpec>& curds, uint32_t value) {
  std::vector<size_t> out;
  size_t first = 0;
  for (const CurdGroup& g : curd_groups(curds)) {
    const uint32_t state = g.state(value);
    if (state != 0 && state <= g.states() - 1) out.push_back(first + state - 1);
    first += g.states() - 1;
  }
  return out;
}

std::vector<double> state_shares(const MarkovChain& chain, int stage) {
  std::vector<double> share(chain.start.size());
  for (size_t i = 0; i < share.size(); ++i) share[i] = chain.start[i].value();
  for (int k = 1; k <= stage; ++k) {
    std::vector<double> next(share.size(), 0.0);
    for (size_t i = 0; i < share.size(); ++i)
      for (size_t j = 0; j < share.size(); ++j) next[j] += share[i] * chain.row(k, i)[j].value();
    share = std::move(next);
  }
  return share;
}

}  // namespace curdle
