// A stage's parents split into tasks for TBB: ranges of kParentsPerTask bits, a multiple of 64,
// so that tasks write disjoint words of the children's bitset (a parent's b^E children are
// consecutive bits). Small stages run in the caller's thread.
#pragma once

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>

namespace curdle {

inline constexpr uint64_t kParentsPerTask = 64 * 128;

// Calls run(begin, end) over [0, parents) in tasks.
template <class Run>
void in_parent_tasks(uint64_t parents, Run&& run) {
  if (parents <= kParentsPerTask) {
    run(uint64_t{0}, parents);
    return;
  }
  const uint64_t tasks = (parents + kParentsPerTask - 1) / kParentsPerTask;
  tbb::parallel_for(uint64_t{0}, tasks, [&](uint64_t t) {
    run(t * kParentsPerTask, std::min(parents, (t + 1) * kParentsPerTask));
  });
}

}  // namespace curdle
