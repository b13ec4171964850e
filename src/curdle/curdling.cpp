#include "curdle/curdling.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include "curdle/error.h"
#include "curdle/random_stream.h"
#include "curdle/theory.h"

namespace curdle {
namespace {

constexpr uint64_t kLow56 = (uint64_t{1} << 56) - 1;
constexpr uint64_t kParentsPerTask = 64 * 128;  // a multiple of 64: tasks write disjoint words

std::string human_bytes(uint64_t bytes) {
  char buf[64];
  const double gib = static_cast<double>(bytes) / (1024.0 * 1024.0 * 1024.0);
  if (gib >= 1.0)
    std::snprintf(buf, sizeof buf, "%.2f GiB", gib);
  else
    std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return buf;
}

// What a stage's kernel needs to know, fixed for the stage.
struct StageWork {
  const CellIndex& index;
  const Box& box;
  bool prune;  // false when the box covers all the roots: every child is inside
  const RandomStream& rng;
  uint32_t curd;
  int stage;
  const Probability& p;
  uint64_t children;  // b^E
  const std::vector<std::array<uint8_t, 3>>& child_digits;
};

// Which children of a parent meet the box: one bit per child digit along each axis.
struct ChildFilter {
  std::array<uint64_t, 3> axis{~uint64_t{0}, ~uint64_t{0}, ~uint64_t{0}};
  bool all = true;

  bool allows(const std::array<uint8_t, 3>& digits) const {
    return ((axis[0] >> digits[0]) & (axis[1] >> digits[1]) & (axis[2] >> digits[2]) & 1) != 0;
  }
};

ChildFilter filter_children(const StageWork& w, uint64_t parent_index) {
  ChildFilter f;
  if (!w.prune) return f;
  const Lattice& l = w.index.lattice();
  const Coord parent = w.index.decode(w.stage - 1, parent_index);
  const int64_t s = static_cast<int64_t>(l.side_in_cells(w.stage));
  for (int d = 0; d < l.dimension; ++d) {
    uint64_t mask = 0;
    const int64_t lo = w.box.origin[d], hi = w.box.origin[d] + w.box.size[d];
    for (int delta = 0; delta < l.base; ++delta) {
      const int64_t start = (parent[d] * l.base + delta) * s;
      if (start < hi && start + s > lo) mask |= uint64_t{1} << delta;
    }
    f.axis[d] = mask;
    if (mask != (l.base == 64 ? ~uint64_t{0} : (uint64_t{1} << l.base) - 1)) f.all = false;
  }
  return f;
}

uint64_t allowed_bits(const StageWork& w, const ChildFilter& f, uint64_t first, unsigned count) {
  if (f.all) return count == 64 ? ~uint64_t{0} : (uint64_t{1} << count) - 1;
  uint64_t bits = 0;
  for (unsigned i = 0; i < count; ++i)
    bits |= uint64_t{f.allows(w.child_digits[first + i])} << i;
  return bits;
}

// Survival of 16 children (16 * block ...) of one parent, canonical mode. Exactly
// P = threshold / 2^64 per child: compare one byte, and on a tie the next 56 bits.
uint32_t survival_block(const StageWork& w, uint64_t path, uint32_t root, uint32_t block,
                        unsigned count) {
  const uint64_t threshold = w.p.threshold();
  if (w.p.certain()) return count == 32 ? ~0u : (1u << count) - 1;
  if (threshold == 0) return 0;
  const auto r = w.rng.draw(path, root, w.curd, w.stage, DrawKind::survival, block);
  const uint32_t top = static_cast<uint32_t>(threshold >> 56);
  uint32_t below = 0, tie = 0;
  for (unsigned word = 0; word < 4; ++word) {
    const uint32_t x = r[word];
    for (unsigned q = 0; q < 4; ++q) {
      const uint32_t u = (x >> (8 * q)) & 0xff;
      below |= static_cast<uint32_t>(u < top) << (4 * word + q);
      tie |= static_cast<uint32_t>(u == top) << (4 * word + q);
    }
  }
  const uint32_t keep = count >= 16 ? 0xffffu : (1u << count) - 1;
  tie &= keep;
  while (tie) {
    const unsigned bit = std::countr_zero(tie);
    const auto t = w.rng.draw(path, root, w.curd, w.stage, DrawKind::tie_break, block * 16 + bit);
    if ((RandomStream::high_word(t) >> 8) < (threshold & kLow56)) below |= 1u << bit;
    tie &= tie - 1;
  }
  return below & keep;
}

// Exact mode: the parent keeps the m = p * b^E children with the smallest keys.
void exact_children(const StageWork& w, uint64_t path, uint32_t root, uint64_t keep,
                    std::vector<std::pair<uint64_t, uint32_t>>& keys, std::vector<uint64_t>& out) {
  const uint64_t n = w.children;
  keys.resize(n);
  for (uint64_t j = 0; 2 * j < n; ++j) {
    const auto r = w.rng.draw(path, root, w.curd, w.stage, DrawKind::exact_key,
                              static_cast<uint32_t>(j));
    keys[2 * j] = {RandomStream::high_word(r), static_cast<uint32_t>(2 * j)};
    if (2 * j + 1 < n) keys[2 * j + 1] = {RandomStream::low_word(r), static_cast<uint32_t>(2 * j + 1)};
  }
  out.assign((n + 63) / 64, 0);
  if (keep == 0) return;
  if (keep < n) std::nth_element(keys.begin(), keys.begin() + (keep - 1), keys.end());
  for (uint64_t i = 0; i < keep; ++i) out[keys[i].second >> 6] |= uint64_t{1} << (keys[i].second & 63);
}

// Visits every set parent bit in [begin, end) of stage k-1 with its root and path.
template <class F>
void for_each_parent(const StageWork& w, const Bitset& parents, uint64_t begin, uint64_t end,
                     F&& f) {
  const uint64_t per_root = w.index.lattice().cells_per_root(w.stage - 1);
  uint64_t root = begin / per_root;
  uint64_t root_start = root * per_root;
  uint32_t code = w.index.root_code(root);
  for_each_set(parents, begin, end, [&](uint64_t i) {
    if (i >= root_start + per_root) {
      root = i / per_root;
      root_start = root * per_root;
      code = w.index.root_code(root);
    }
    f(i, i - root_start, code);
  });
}

void canonical_or_exact_stage(const StageWork& w, const Bitset& parents, Bitset& children) {
  const uint64_t B = w.children;
  const uint64_t exact_keep = w.index.lattice().mode == Mode::exact ? w.p.round_times(B) : 0;
  const bool exact = w.index.lattice().mode == Mode::exact;
  auto run = [&](uint64_t begin, uint64_t end) {
    std::vector<std::pair<uint64_t, uint32_t>> keys;
    std::vector<uint64_t> chosen;
    for_each_parent(w, parents, begin, end, [&](uint64_t i, uint64_t path, uint32_t code) {
      const ChildFilter filter = filter_children(w, i);
      const uint64_t first_child = i * B;
      if (exact) {
        exact_children(w, path, code, exact_keep, keys, chosen);
        for (uint64_t c = 0; c < B; c += 64) {
          const unsigned count = static_cast<unsigned>(std::min<uint64_t>(64, B - c));
          const uint64_t bits = chosen[c / 64] & allowed_bits(w, filter, c, count);
          if (bits) children.or_bits(first_child + c, bits, count);
        }
        return;
      }
      for (uint64_t c = 0; c < B; c += 16) {
        const unsigned count = static_cast<unsigned>(std::min<uint64_t>(16, B - c));
        uint64_t bits = survival_block(w, path, code, static_cast<uint32_t>(c / 16), count);
        if (bits) bits &= allowed_bits(w, filter, c, count);
        if (bits) children.or_bits(first_child + c, bits, count);
      }
    });
  };
  const uint64_t n = parents.size;
  if (n <= kParentsPerTask) {
    run(0, n);
    return;
  }
  const uint64_t tasks = (n + kParentsPerTask - 1) / kParentsPerTask;
  tbb::parallel_for(uint64_t{0}, tasks, [&](uint64_t t) {
    run(t * kParentsPerTask, std::min(n, (t + 1) * kParentsPerTask));
  });
}

// Quota mode: of all candidates (children of survivors inside the field), exactly `target`
// survive: those with the smallest (key, bit index). Found in three passes over the keys
// (histogram of the top 16 bits, the boundary bucket, the cut) so that memory stays small
// however many candidates there are.
void quota_stage(const StageWork& w, uint64_t target, const Bitset& parents, Bitset& children) {
  const uint64_t B = w.children;
  auto for_each_candidate = [&](auto&& f) {
    for_each_parent(w, parents, 0, parents.size, [&](uint64_t i, uint64_t path, uint32_t code) {
      const ChildFilter filter = filter_children(w, i);
      for (uint64_t c = 0; c < B; ++c) {
        if (!filter.all && !filter.allows(w.child_digits[c])) continue;
        const auto r = w.rng.draw(path * B + c, code, w.curd, w.stage, DrawKind::quota_key, 0);
        f(RandomStream::high_word(r), i * B + c);
      }
    });
  };
  std::vector<uint64_t> histogram(1 << 16, 0);
  uint64_t candidates = 0;
  for_each_candidate([&](uint64_t key, uint64_t) {
    ++histogram[key >> 48];
    ++candidates;
  });
  const uint64_t keep = std::min(target, candidates);
  if (keep == 0) return;
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
    if ((key >> 48) < bucket || ((key >> 48) == bucket && std::pair{key, bit} <= cut))
      children.set(bit);
  });
}

std::vector<std::array<uint8_t, 3>> child_digits(const Lattice& l) {
  std::vector<std::array<uint8_t, 3>> digits(l.children(), {0, 0, 0});
  for (uint64_t t = 0; t < digits.size(); ++t) {
    uint64_t rest = t;
    for (int d = 0; d < l.dimension; ++d) {
      digits[t][d] = static_cast<uint8_t>(rest % l.base);
      rest /= l.base;
    }
  }
  return digits;
}

}  // namespace

uint64_t quota_target(const std::vector<Probability>& p, int stage, uint64_t cells) {
  // Exact rational product where every probability is rational and it fits; else doubles.
  unsigned __int128 num = cells, den = 1;
  bool exact = true;
  for (int i = 0; i < stage && exact; ++i) {
    if (!p[i].is_rational()) {
      exact = false;
      break;
    }
    num *= p[i].numerator();
    den *= p[i].denominator();
    const unsigned __int128 g = std::gcd(static_cast<uint64_t>(num % den), static_cast<uint64_t>(den));
    if (g > 1) num /= g, den /= g;
    if (num >> 100 || den >> 62) exact = false;
  }
  if (exact) return static_cast<uint64_t>((2 * num + den) / (2 * den));
  return static_cast<uint64_t>(std::floor(static_cast<double>(cells) * survival_probability(p, stage) + 0.5));
}

Box generation_box(const Design& design, const Box& view) {
  return design.lattice.mode == Mode::quota ? design.field : view;
}

uint64_t estimate_memory(const Design& design, const Box& box) {
  const CellIndex index(design.lattice, box);
  uint64_t words = 0;
  for (int k = 0; k <= design.lattice.stages; ++k)
    words += (index.roots() * design.lattice.cells_per_root(k) + 63) / 64;
  return words * 8 * design.curds.size();
}

CurdField curdle(const Design& design, uint64_t seed, const Box& view,
                 const GenerateOptions& options) {
  CurdField field;
  curdle_into(design, seed, view, field, options);
  return field;
}

void curdle_into(const Design& design, uint64_t seed, const Box& view, CurdField& out,
                 const GenerateOptions& options) {
  const Lattice& lattice = design.lattice;
  const Box box = generation_box(design, view);
  if (options.max_memory_bytes != 0) {
    const uint64_t need = estimate_memory(design, box);
    if (need > options.max_memory_bytes)
      throw InputError("generating " + std::to_string(box.cells()) + " cells x " +
                       std::to_string(design.curds.size()) + " curds needs about " +
                       human_bytes(need) + ", above the memory limit of " +
                       human_bytes(options.max_memory_bytes) +
                       "; use a smaller field, window or fewer stages" +
                       (options.memory_limit_hint.empty() ? "" : ", or " + options.memory_limit_hint));
  }
  out.index = CellIndex(lattice, box);
  out.generated = box;
  out.curds.resize(design.curds.size());

  const RandomStream rng(seed);
  const auto digits = child_digits(lattice);
  const bool prune = !(box == out.index.covered_cells());
  const double total_work = static_cast<double>(design.curds.size() * lattice.stages);
  double done = 0;
  for (size_t c = 0; c < design.curds.size(); ++c) {
    Curd& curd = out.curds[c];
    curd.stages.resize(lattice.stages + 1);
    curd.stages[0].assign_zero(out.index.roots());
    for (uint64_t r = 0; r < out.index.roots(); ++r) curd.stages[0].set(r);
    for (int k = 1; k <= lattice.stages; ++k) {
      curd.stages[k].assign_zero(out.index.roots() * lattice.cells_per_root(k));
      const StageWork work{out.index, box, prune, rng, static_cast<uint32_t>(c), k,
                           design.curds[c].probabilities[k - 1], lattice.children(), digits};
      if (lattice.mode == Mode::quota)
        quota_stage(work, quota_target(design.curds[c].probabilities, k,
                                       cells_meeting(lattice, k, box)),
                    curd.stages[k - 1], curd.stages[k]);
      else
        canonical_or_exact_stage(work, curd.stages[k - 1], curd.stages[k]);
      if (options.progress) options.progress(++done / total_work);
    }
  }
}

}  // namespace curdle
