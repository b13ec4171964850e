// Drawing a Markov curd's planes (markov.h), stage by stage, from the counter-based stream of
// plain curds (random_stream.h), keyed by the chain's first plane as its curd:
//   roots     a start distribution draws the root's own uniform u (kind 0 byte 0 of path 0 at
//             stage 0, then kind 1 when that byte does not decide); a start state draws nothing;
//   canonical each child takes the state its uniform u falls in (StateBounds): u's top byte
//             is the child's survival byte (kind 0) and its low 56 bits its tie break (kind 1),
//             drawn only when the top byte does not decide. One living state is a plain curd;
//   exact     a state-i parent's children, ordered by their exact-mode keys (kind 2), take the
//             states 1, 2, ... in turn, n_j = P[i][j] b^E of each (a whole number, as exact mode
//             requires), the rest dead: the first n_1 are the plain curd's survivors;
//   quota     over the whole field, state j gets round(C_k (s_1 + ... + s_j)) minus what the
//             states before it got, s the stage's expected shares (markov.h state_shares): the
//             still unassigned children with the smallest keys -log(1 - u)/P[i][j] (u from kind
//             3, block j - 1; Efraimidis and Spirakis' weighted sampling), in state order.
// Dead parents have children only where the dead row gives life (wheys).
#pragma once

#include <cstdint>
#include <span>

#include "curdle/curd.h"
#include "curdle/markov.h"
#include "curdle/random_stream.h"

namespace curdle {

struct MarkovWork {
  const CellIndex& index;
  const Box& box;
  bool prune;  // false when the box covers all the roots
  Mode mode;
  const RandomStream& rng;
  uint32_t curd;  // the chain's first plane: its curd in the stream
  const MarkovChain& chain;
};

// Stage 0: every root's state, into planes[p].stages[0] (already sized and zero).
void markov_roots(const MarkovWork& w, std::span<Curd> planes);

// Stage k from stage k - 1, into planes[p].stages[k] (already sized and zero). In quota mode
// `field_cells` is the number of stage-k cells meeting the field; returns, per living state,
// how many of its quota could not be met (empty unless some fell short).
std::vector<uint64_t> markov_stage(const MarkovWork& w, int stage, std::span<Curd> planes,
                                   uint64_t field_cells);

// The state of cell `index` at `stage`, read from the planes.
inline uint32_t state_at(std::span<const Curd> planes, int stage, uint64_t index) {
  uint32_t s = 0;
  for (size_t p = 0; p < planes.size(); ++p)
    s |= static_cast<uint32_t>(planes[p].stages[static_cast<size_t>(stage)].test(index)) << p;
  return s;
}

}  // namespace curdle
