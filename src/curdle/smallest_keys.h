// Choosing the `keep` candidates with the smallest (key, bit) over a whole field without holding
// them: three passes over the candidates (a histogram of the keys' top 16 bits, the boundary
// bucket, the cut), so that memory stays small however many candidates there are. Quota mode's
// choice, for plain curds and Markov curds alike.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace curdle {

// `for_each_candidate(f)` calls f(key, bit) for every candidate, the same ones in the same
// order each time; `chosen(bit)` hears the winners. Returns how many were chosen: fewer than
// `keep` only when there were fewer candidates.
template <class ForEachCandidate, class Chosen>
uint64_t choose_smallest_keys(uint64_t keep, ForEachCandidate&& for_each_candidate,
                              Chosen&& chosen) {
  std::vector<uint64_t> histogram(1 << 16, 0);
  uint64_t candidates = 0;
  for_each_candidate([&](uint64_t key, uint64_t) {
    ++histogram[key >> 48];
    ++candidates;
  });
  keep = std::min(keep, candidates);
  if (keep == 0) return 0;
  uint64_t below = 0;
  uint64_t bucket = 0;
  while (below + histogram[bucket] < keep) below += histogram[bucket++];
  std::vector<std::pair<uint64_t, uint64_t>> boundary;
  boundary.reserve(histogram[bucket]);
  for_each_candidate([&](uint64_t key, uint64_t bit) {
    if ((key >> 48) == bucket) boundary.emplace_back(key, bit);
  });
  const auto cut_at = boundary.begin() + static_cast<int64_t>(keep - below - 1);
  std::nth_element(boundary.begin(), cut_at, boundary.end());
  const std::pair<uint64_t, uint64_t> cut = *cut_at;
  for_each_candidate([&](uint64_t key, uint64_t bit) {
    if ((key >> 48) < bucket || ((key >> 48) == bucket && std::pair{key, bit} <= cut)) chosen(bit);
  });
  return keep;
}

}  // namespace curdle
