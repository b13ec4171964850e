#include "curdle/boxcount.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <array>
#include <bit>
#include <cmath>
#include <functional>

namespace curdle {

namespace {

// Aligned groups of g bits (g a power of two, 1..64) of x with a set bit: fold each group onto
// its first bit, then count the first bits (`starts`).
inline unsigned nonzero_groups(uint64_t x, uint64_t g, uint64_t starts) {
  for (uint64_t s = 1; s < g; s <<= 1) x |= x >> s;
  return static_cast<unsigned>(std::popcount(x & starts));
}

inline uint64_t group_starts(uint64_t g) {
  return g == 64 ? 1 : g == 1 ? ~uint64_t{0} : ~uint64_t{0} / ((uint64_t{1} << g) - 1);
}

// When b^E is a power of two the descendants of a stage-j cell are an aligned group of
// (b^E)^(K-j) final bits, so the box count at level j is the number of non-zero groups of
// that size. Groups up to a word are counted by folding each word; larger ones by recursing
// on the map of non-zero words (one bit per word), 64 times smaller each time.
struct GroupLevel {
  uint64_t group;  // in bits of the array being read
  uint64_t* count;
};

// Which words of a stage can hold a survivor: those under a survivor of a coarser stage whose
// cells each cover whole words. The finest stages are sparse (a p = 0.7 plane keeps under 1 %
// of its cells), and reading only these words never touches, nor faults in, the rest.
struct LiveWords {
  const Bitset* coarse = nullptr;  // null: every word
  uint64_t words_per_bit = 0;
};

LiveWords live_words(const Curd& curd, int k, uint64_t children) {
  if (!std::has_single_bit(children) || children >= 64) return {};
  uint64_t span = 1;  // finest bits under one cell of stage k - up
  int up = 0;
  while (span < 64) span *= children, ++up;
  // Worth it only when the coarse stage is much smaller than the one scanned.
  if (k - up < 1 || curd.stages[k].words.size() < (1u << 14)) return {};
  return LiveWords{&curd.stages[k - up], span / 64};
}

// Calls f(begin, end) for the runs of live words among coarse bits [begin_bit, end_bit), or of
// all words in that range of words when there is no coarse stage.
template <class F>
void for_each_live_run(const LiveWords& live, uint64_t begin, uint64_t end, F&& f) {
  if (!live.coarse) {
    f(begin, end);
    return;
  }
  uint64_t run_begin = 0, run_end = 0;
  for_each_set(*live.coarse, begin, end, [&](uint64_t i) {
    const uint64_t b = i * live.words_per_bit;
    if (b != run_end) {
      if (run_end > run_begin) f(run_begin, run_end);
      run_begin = b;
    }
    run_end = b + live.words_per_bit;
  });
  if (run_end > run_begin) f(run_begin, run_end);
}

void count_groups(const uint64_t* words, size_t n, GroupLevel* levels, size_t count) {
  size_t in_word = 0;
  while (in_word < count && levels[in_word].group <= 64) ++in_word;
  const bool beyond = in_word < count;
  const size_t map_words = (n + 63) / 64;
  std::array<uint64_t, 64> small_map;
  std::vector<uint64_t> large_map;
  uint64_t* map = small_map.data();
  if (beyond) {
    if (map_words > small_map.size()) {
      large_map.assign(map_words, 0);
      map = large_map.data();
    } else {
      std::fill_n(map, map_words, 0);
    }
  }
  std::array<uint64_t, 64> starts;
  for (size_t i = 0; i < in_word; ++i) starts[i] = group_starts(levels[i].group);
  std::array<uint64_t, 64> sums{};
  auto pass = [&](size_t begin, size_t end, std::array<uint64_t, 64>& acc) {
    for (size_t w = begin; w < end; ++w) {
      const uint64_t x = words[w];
      if (!x) continue;
      for (size_t i = 0; i < in_word; ++i) acc[i] += nonzero_groups(x, levels[i].group, starts[i]);
      if (beyond) map[w >> 6] |= uint64_t{1} << (w & 63);
    }
  };
  constexpr size_t kWordsPerTask = 64 * 256;  // whole words of the map per task
  if (n <= kWordsPerTask) {
    pass(0, n, sums);
  } else {
    sums = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, (n + kWordsPerTask - 1) / kWordsPerTask), sums,
        [&](const tbb::blocked_range<size_t>& r, std::array<uint64_t, 64> acc) {
          pass(r.begin() * kWordsPerTask, std::min(n, r.end() * kWordsPerTask), acc);
          return acc;
        },
        [](std::array<uint64_t, 64> a, const std::array<uint64_t, 64>& b) {
          for (size_t i = 0; i < a.size(); ++i) a[i] += b[i];
          return a;
        });
  }
  for (size_t i = 0; i < in_word; ++i) *levels[i].count = sums[i];
  if (!beyond) return;
  for (size_t i = in_word; i < count; ++i) levels[i].group /= 64;
  count_groups(map, map_words, levels + in_word, count - in_word);
}

// count_groups on a sparse finest stage: only the words under live coarse cells are read.
// Groups up to a word are folded as above; a larger group is a group of coarse cells, so its
// count is the number of distinct ancestors of the coarse cells with a final survivor, found
// in one ordered pass (tasks join where an ancestor straddles their boundary).
void count_groups_live(const uint64_t* words, const LiveWords& live, GroupLevel* levels,
                       size_t count) {
  const uint64_t span = live.words_per_bit * 64;  // finest bits per coarse cell
  size_t in_word = 0;
  while (in_word < count && levels[in_word].group <= 64) ++in_word;
  std::array<uint64_t, 64> starts;
  std::array<int, 64> shift;  // ancestor of coarse cell i at a large level: i >> shift
  for (size_t i = 0; i < count; ++i) {
    if (i < in_word)
      starts[i] = group_starts(levels[i].group);
    else
      shift[i] = std::countr_zero(levels[i].group / span);
  }
  struct Partial {
    std::array<uint64_t, 64> sums{};
    std::array<uint64_t, 64> first{}, last{};  // ancestors at the ends, per large level
    bool any = false;
  };
  auto pass = [&](uint64_t begin, uint64_t end, Partial& acc) {
    for_each_set(*live.coarse, begin, end, [&](uint64_t cell) {
      bool alive = false;
      for (uint64_t w = cell * live.words_per_bit; w < (cell + 1) * live.words_per_bit; ++w) {
        const uint64_t x = words[w];
        if (!x) continue;
        alive = true;
        for (size_t i = 0; i < in_word; ++i)
          acc.sums[i] += nonzero_groups(x, levels[i].group, starts[i]);
      }
      if (!alive) return;
      for (size_t i = in_word; i < count; ++i) {
        const uint64_t ancestor = cell >> shift[i];
        if (!acc.any) acc.first[i] = ancestor;
        if (!acc.any || ancestor != acc.last[i]) ++acc.sums[i];
        acc.last[i] = ancestor;
      }
      acc.any = true;
    });
  };
  auto join = [&](Partial a, const Partial& b) {
    if (!b.any) return a;
    if (!a.any) return b;
    for (size_t i = 0; i < count; ++i) {
      a.sums[i] += b.sums[i];
      if (i >= in_word && a.last[i] == b.first[i]) --a.sums[i];
      a.last[i] = b.last[i];
    }
    return a;
  };
  constexpr uint64_t kCellsPerTask = 64 * 256;
  const uint64_t cells = live.coarse->size;
  Partial total;
  if (cells <= kCellsPerTask) {
    pass(0, cells, total);
  } else {
    // parallel_reduce keeps the order of its operands: join(left, right).
    total = tbb::parallel_reduce(
        tbb::blocked_range<uint64_t>(0, (cells + kCellsPerTask - 1) / kCellsPerTask), Partial{},
        [&](const tbb::blocked_range<uint64_t>& r, Partial acc) {
          Partial own;
          pass(r.begin() * kCellsPerTask, std::min(cells, r.end() * kCellsPerTask), own);
          return join(acc, own);
        },
        join);
  }
  for (size_t i = 0; i < count; ++i) *levels[i].count = total.sums[i];
}

}  // namespace

std::vector<uint64_t> box_counts(const Curd& curd, uint64_t children,
                                 std::vector<Bitset>& scratch) {
  std::vector<uint64_t> counts;
  box_counts_into(curd, children, scratch, counts);
  return counts;
}

void box_counts_into(const Curd& curd, uint64_t children, std::vector<Bitset>& scratch,
                     std::vector<uint64_t>& counts) {
  const int K = static_cast<int>(curd.stages.size()) - 1;
  counts.assign(static_cast<size_t>(K) + 1, 0);
  if (std::has_single_bit(children)) {
    std::array<GroupLevel, 64> levels;
    uint64_t group = 1;
    for (int j = K; j >= 0; --j, group *= children) levels[K - j] = GroupLevel{group, &counts[j]};
    const LiveWords live = live_words(curd, K, children);
    if (live.coarse)
      count_groups_live(curd.stages[K].words.data(), live, levels.data(), K + 1);
    else
      count_groups(curd.stages[K].words.data(), curd.stages[K].words.size(), levels.data(), K + 1);
    return;
  }
  counts[K] = curd.stages[K].count();
  scratch.resize(2);
  const Bitset* below = &curd.stages[K];
  for (int j = K - 1; j >= 0; --j) {
    Bitset& alive = scratch[j & 1];
    const Bitset& stage = curd.stages[j];
    alive.assign_zero(stage.size);
    // Only survivors of stage j can have surviving descendants. Ranges of whole words, so
    // that tasks write disjoint words.
    // When b^E divides 64 a cell's children are a field of one word: test it directly.
    const bool in_one_word = 64 % children == 0;
    const uint64_t field = children >= 64 ? ~uint64_t{0} : (uint64_t{1} << children) - 1;
    auto mark = [&](uint64_t begin, uint64_t end) {
      uint64_t n = 0;
      for_each_set(stage, begin, end, [&](uint64_t i) {
        const uint64_t first = i * children;
        const bool any = in_one_word ? ((below->words[first >> 6] >> (first & 63)) & field) != 0
                                     : below->any_in(first, first + children);
        if (any) {
          alive.set(i);
          ++n;
        }
      });
      return n;
    };
    constexpr uint64_t kBitsPerTask = 64 * 1024;
    if (stage.size <= kBitsPerTask) {
      counts[j] = mark(0, stage.size);
    } else {
      counts[j] = tbb::parallel_reduce(
          tbb::blocked_range<uint64_t>(0, (stage.size + kBitsPerTask - 1) / kBitsPerTask),
          uint64_t{0},
          [&](const tbb::blocked_range<uint64_t>& r, uint64_t n) {
            return n + mark(r.begin() * kBitsPerTask, std::min(stage.size, r.end() * kBitsPerTask));
          },
          std::plus<>());
    }
    below = &alive;
  }
}

uint64_t count_survivors(const Curd& curd, int stage, uint64_t children) {
  const Bitset& bits = curd.stages[stage];
  const LiveWords live = live_words(curd, stage, children);
  if (!live.coarse) return bits.count();
  const uint64_t* w = bits.words.data();
  uint64_t n = 0;
  for_each_live_run(live, 0, live.coarse->size, [&](uint64_t b, uint64_t e) {
    for (uint64_t i = b; i < e; ++i) n += std::popcount(w[i]);
  });
  return n;
}

std::vector<uint64_t> box_counts(const Curd& curd, uint64_t children) {
  std::vector<Bitset> scratch;
  return box_counts(curd, children, scratch);
}

std::optional<LineFit> fit_box_dimension(const std::vector<uint64_t>& counts, int base) {
  return fit_box_dimension(std::vector<double>(counts.begin(), counts.end()), base);
}

std::optional<LineFit> fit_box_dimension(const std::vector<double>& counts, int base) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  int n = 0;
  for (size_t j = 0; j < counts.size(); ++j) {
    if (!(counts[j] > 0)) continue;
    const double x = static_cast<double>(j) * std::log(static_cast<double>(base));
    const double y = std::log(static_cast<double>(counts[j]));
    sx += x, sy += y, sxx += x * x, sxy += x * y, syy += y * y;
    ++n;
  }
  if (n < 2) return std::nullopt;
  const double vx = sxx - sx * sx / n, vy = syy - sy * sy / n, cxy = sxy - sx * sy / n;
  LineFit fit;
  fit.slope = cxy / vx;
  fit.r2 = vy > 0 ? (cxy * cxy) / (vx * vy) : 1.0;
  fit.points = n;
  return fit;
}

}  // namespace curdle
