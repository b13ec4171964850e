#include "curdle/curdling.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include "curdle/child_filter.h"
#include "curdle/error.h"
#include "curdle/markov_curdling.h"
#include "curdle/parent_tasks.h"
#include "curdle/philox_batch.h"
#include "curdle/random_stream.h"
#include "curdle/smallest_keys.h"
#include "curdle/stop.h"
#include "curdle/survival_bytes.h"
#include "curdle/theory.h"

namespace curdle {
namespace {

constexpr uint64_t kLow56 = (uint64_t{1} << 56) - 1;

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
  Mode mode;
  const RandomStream& rng;
  uint32_t curd;
  int stage;
  const Probability& p;
  uint64_t children;               // b^E
  const DensityField* density;     // null: every child survives with p
  double product_before, product;  // P_(k-1) and P_k, for a density field
};

inline ChildFilter filter_children(const StageWork& w, uint64_t parent_index) {
  return w.prune ? children_in_box(w.index, w.box, w.stage, parent_index) : ChildFilter{};
}

uint64_t low_bits(unsigned count) {
  return count >= 64 ? ~uint64_t{0} : (uint64_t{1} << count) - 1;
}

uint64_t allowed_bits(const StageWork& w, const ChildFilter& f, uint64_t first, unsigned count) {
  if (f.all) return low_bits(count);
  const auto& digits = w.index.child_digits();
  uint64_t bits = 0;
  for (unsigned i = 0; i < count; ++i) bits |= uint64_t{f.allows(digits[first + i])} << i;
  return bits;
}

// Canonical survival for a batch of parents, keyed by the children's paths (random_stream.h,
// kind 0). The draws of a whole batch are made in one tight loop, so that the generator's
// latency overlaps between parents; neighbouring parents share a draw when b^E < 16.
class SurvivalBatch {
 public:
  static constexpr size_t kParents = 64;

  SurvivalBatch(const StageWork& w, Bitset& children)
      : w_(w),
        children_(children),
        threshold_(w.p.threshold()),
        top_(static_cast<uint32_t>(threshold_ >> 56)),
        buffers_(thread_buffers()) {
    // At most b^E/16 + 1 draws a parent, in whole vectors of eight.
    const size_t most = (kParents * (w.children / 16 + 2) + 7) / 8 * 8;
    if (buffers_.blocks.size() < most) {
      buffers_.blocks.resize(most);
      for (auto* v : {&buffers_.w0, &buffers_.w1, &buffers_.w2, &buffers_.w3}) v->resize(most);
      buffers_.below.resize(most);
      buffers_.tie.resize(most);
    }
  }
  ~SurvivalBatch() { flush(); }

  void add(uint64_t index, uint64_t path, uint32_t root) {
    parents_[count_++] = Parent{index, path, root, 0};
    if (count_ == kParents) flush();
  }

  void flush() {
    if (count_ == 0) return;
    const uint64_t B = w_.children;
    if (B % 16 == 0) {
      flush_whole_draws();
      return;
    }
    if (16 % B == 0 && !w_.prune) {
      flush_small_families();
      return;
    }
    Block* blocks = buffers_.blocks.data();
    size_t n = 0;
    for (size_t p = 0; p < count_; ++p) {
      Parent& parent = parents_[p];
      const uint64_t first = parent.path * B >> 4, last = (parent.path * B + B - 1) >> 4;
      for (uint64_t b = first; b <= last; ++b) {
        const bool shared = n > 0 && blocks[n - 1].block == b && blocks[n - 1].root == parent.root;
        if (b == first) parent.first_block = n - (shared ? 1 : 0);
        if (!shared) blocks[n++] = Block{b, parent.root, 0, 0};
      }
    }
    draw_all(n);
    for (size_t i = 0; i < n; ++i)
      if (blocks[i].tie)  // rare: 1 in 16 draws
        blocks[i].below =
            decide_ties(blocks[i].block, blocks[i].root, blocks[i].below, blocks[i].tie);
    for (size_t p = 0; p < count_; ++p) write_children(parents_[p]);
    count_ = 0;
  }

 private:
  struct Parent {
    uint64_t index, path;
    uint32_t root;
    size_t first_block;
  };
  struct Block {
    uint64_t block;
    uint32_t root;
    uint32_t below, tie;
  };

  // b^E a multiple of 16: each parent owns b^E/16 whole draws, so counters go straight into
  // the generator's arrays and each parent's bits come straight out of its draws.
  void flush_whole_draws() {
    Buffers& b = buffers_;
    const uint64_t B = w_.children, per_parent = B >> 4;
    const uint32_t tag = RandomStream::tag(w_.curd, w_.stage, DrawKind::survival, 0);
    size_t n = 0;
    for (size_t p = 0; p < count_; ++p) {
      const Parent& parent = parents_[p];
      for (uint64_t block = parent.path * per_parent; block < (parent.path + 1) * per_parent;
           ++block) {
        b.w0[n] = static_cast<uint32_t>(block);
        b.w1[n] = static_cast<uint32_t>(block >> 32);
        b.w2[n] = parent.root;
        b.w3[n++] = tag;
      }
    }
    draw_lanes(n);
    if (B == 16) {
      write_one_draw_families();
      return;
    }
    size_t i = 0;
    for (size_t p = 0; p < count_; ++p) {
      const Parent& parent = parents_[p];
      const ChildFilter filter = filter_children(w_, parent.index);
      for (uint64_t c = 0; c < B; c += 64) {
        const unsigned count = static_cast<unsigned>(std::min<uint64_t>(64, B - c));
        uint64_t bits = 0;
        for (unsigned done = 0; done < count; done += 16, ++i) {
          uint32_t below = b.below[i];
          if (b.tie[i])  // rare: 1 in 16 draws
            below = decide_ties((parent.path * B + c + done) >> 4, parent.root, below, b.tie[i]);
          bits |= static_cast<uint64_t>(below) << done;
        }
        if (bits && !filter.all) bits &= allowed_bits(w_, filter, c, count);
        if (bits) children_.or_bits(parent.index * B + c, bits, count);
      }
    }
    count_ = 0;
  }

  // b^E = 16 (b = 4 in 2-D): draw p is parent p's children, one 16-bit field of one word; the
  // same bits as the loop above without its bookkeeping (a seed search 1.4 times as fast).
  void write_one_draw_families() {
    Buffers& b = buffers_;
    uint64_t* words = children_.words.data();
    for (size_t p = 0; p < count_; ++p) {
      const Parent& parent = parents_[p];
      uint32_t below = b.below[p];
      if (b.tie[p]) below = decide_ties(parent.path, parent.root, below, b.tie[p]);  // 1 in 16
      if (below && w_.prune) {
        const ChildFilter filter = filter_children(w_, parent.index);
        if (!filter.all) below &= static_cast<uint32_t>(allowed_bits(w_, filter, 0, 16));
      }
      const uint64_t first = parent.index * 16;
      if (below) words[first >> 6] |= uint64_t{below} << (first & 63);
    }
    count_ = 0;
  }

  // b^E dividing 16 (b = 2 in 2-D or 3-D, b = 2 or 4 on a line) with every child inside the
  // box: a draw holds the children of 16 / b^E neighbouring parents whole, so each parent's
  // children are one field of one draw and land in one field of one word. The same draws and
  // bits as the general path, with none of its per-child bookkeeping.
  void flush_small_families() {
    Buffers& b = buffers_;
    const uint64_t B = w_.children;
    const uint32_t tag = RandomStream::tag(w_.curd, w_.stage, DrawKind::survival, 0);
    size_t n = 0;
    for (size_t p = 0; p < count_; ++p) {
      Parent& parent = parents_[p];
      const uint64_t block = parent.path * B >> 4;
      if (n == 0 || b.blocks[n - 1].block != block || b.blocks[n - 1].root != parent.root) {
        b.blocks[n] = Block{block, parent.root, 0, 0};
        b.w0[n] = static_cast<uint32_t>(block);
        b.w1[n] = static_cast<uint32_t>(block >> 32);
        b.w2[n] = parent.root;
        b.w3[n++] = tag;
      }
      parent.first_block = n - 1;
    }
    draw_lanes(n);
    for (size_t i = 0; i < n; ++i) {
      if (!b.tie[i]) continue;  // rare: 1 in 16 draws
      const Block& block = b.blocks[i];
      b.below[i] =
          static_cast<uint16_t>(decide_ties(block.block, block.root, b.below[i], b.tie[i]));
    }
    const uint64_t field = (uint64_t{1} << B) - 1;
    uint64_t* words = children_.words.data();
    for (size_t p = 0; p < count_; ++p) {
      const Parent& parent = parents_[p];
      const uint64_t bits = (b.below[parent.first_block] >> (parent.path * B & 15)) & field;
      const uint64_t first = parent.index * B;
      if (bits) words[first >> 6] |= bits << (first & 63);
    }
    count_ = 0;
  }

  // The first n draws of the batch at once (philox_batch.h), then their bytes against the
  // threshold.
  void draw_all(size_t n) {
    Buffers& b = buffers_;
    const uint32_t tag = RandomStream::tag(w_.curd, w_.stage, DrawKind::survival, 0);
    for (size_t i = 0; i < n; ++i) {
      const Block& block = b.blocks[i];
      b.w0[i] = static_cast<uint32_t>(block.block);
      b.w1[i] = static_cast<uint32_t>(block.block >> 32);
      b.w2[i] = block.root;
      b.w3[i] = tag;
    }
    draw_lanes(n);
    for (size_t i = 0; i < n; ++i) {
      b.blocks[i].below = b.below[i];
      b.blocks[i].tie = b.tie[i];
    }
  }

  // Draws the n counters in the buffers' word arrays in place, in whole vectors (the padding
  // draws are discarded), and compares their bytes with the threshold into below and tie.
  void draw_lanes(size_t n) {
    Buffers& b = buffers_;
    const size_t lanes = (n + 7) / 8 * 8;
    for (size_t i = n; i < lanes; ++i) b.w0[i] = b.w1[i] = b.w2[i] = b.w3[i] = 0;
    philox_in_place(b.w0.data(), b.w1.data(), b.w2.data(), b.w3.data(), lanes, w_.rng.key(0),
                    w_.rng.key(1));
    compare_lanes(b.w0.data(), b.w1.data(), b.w2.data(), b.w3.data(), lanes, top_, b.below.data(),
                  b.tie.data());
  }

  // A draw's survivors `below` once its ties on the top byte (bits of `tie`) are decided: the
  // next 56 bits of each tied child decide (kind 1).
  uint32_t decide_ties(uint64_t block, uint32_t root, uint32_t below, uint32_t tie) const {
    // A threshold with no bits below its top byte (p = 1/2, 1/4, ...): a tie is never below.
    if ((threshold_ & kLow56) == 0) return below;
    for (; tie; tie &= tie - 1) {
      const unsigned bit = static_cast<unsigned>(std::countr_zero(tie));
      const auto t = w_.rng.draw(block << 4 | bit, root, w_.curd, w_.stage, DrawKind::tie_break, 0);
      if ((RandomStream::high_word(t) >> 8) < (threshold_ & kLow56)) below |= 1u << bit;
    }
    return below;
  }

  void write_children(const Parent& parent) {
    const Block* blocks = buffers_.blocks.data();
    const uint64_t B = w_.children;
    const ChildFilter filter = filter_children(w_, parent.index);
    size_t block = parent.first_block;
    uint64_t child = parent.path * B;
    for (uint64_t c = 0; c < B; c += 64) {
      const unsigned count = static_cast<unsigned>(std::min<uint64_t>(64, B - c));
      uint64_t bits = 0;
      for (unsigned done = 0; done < count;) {
        const unsigned offset = child & 15;
        const unsigned n = std::min(count - done, 16 - offset);
        const uint32_t keep = static_cast<uint32_t>(low_bits(n)) << offset;
        bits |= static_cast<uint64_t>((blocks[block].below & keep) >> offset) << done;
        done += n;
        child += n;
        if ((child & 15) == 0) ++block;
      }
      if (bits) bits &= allowed_bits(w_, filter, c, count);
      if (bits) children_.or_bits(parent.index * B + c, bits, count);
    }
  }

  const StageWork& w_;
  Bitset& children_;
  uint64_t threshold_;
  uint32_t top_;
  // Per-thread scratch, kept between stages and seeds so that small curds allocate nothing.
  struct Buffers {
    std::vector<Block> blocks;
    std::vector<uint32_t> w0, w1, w2, w3;
    std::vector<uint16_t> below, tie;
  };
  static Buffers& thread_buffers() {
    thread_local Buffers buffers;
    return buffers;
  }

  std::array<Parent, kParents> parents_;
  size_t count_ = 0;
  Buffers& buffers_;
};

// Exact mode: the parent keeps the m = p * b^E children with the smallest keys.
void exact_children(const StageWork& w, uint64_t path, uint32_t root, uint64_t keep,
                    std::vector<std::pair<uint64_t, uint32_t>>& keys, std::vector<uint64_t>& out) {
  const uint64_t n = w.children;
  keys.resize(n);
  for (uint64_t j = 0; 2 * j < n; ++j) {
    const auto r =
        w.rng.draw(path, root, w.curd, w.stage, DrawKind::exact_key, static_cast<uint32_t>(j));
    keys[2 * j] = {RandomStream::high_word(r), static_cast<uint32_t>(2 * j)};
    if (2 * j + 1 < n)
      keys[2 * j + 1] = {RandomStream::low_word(r), static_cast<uint32_t>(2 * j + 1)};
  }
  out.assign((n + 63) / 64, 0);
  if (keep == 0) return;
  if (keep < n) std::nth_element(keys.begin(), keys.begin() + (keep - 1), keys.end());
  for (uint64_t i = 0; i < keep; ++i)
    out[keys[i].second >> 6] |= uint64_t{1} << (keys[i].second & 63);
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

// A density field (density.h): each child survives with its own q = S_k(child) / S_(k-1)(parent),
// drawn from the same bytes and tie breaks as a plain stage, so that P(survive) = q exactly.
void density_children(const StageWork& w, uint64_t index, uint64_t path, uint32_t root,
                      Bitset& children) {
  const DensityField& field = *w.density;
  const Lattice& l = w.index.lattice();
  const Coord parent = w.index.decode(w.stage - 1, index);
  const double before = field.survival(l, w.stage - 1, parent, w.product_before);
  if (!(before > 0)) return;  // a parent that could not survive has no children
  const ChildFilter filter = filter_children(w, index);
  const uint64_t B = w.children;
  const auto& digits = w.index.child_digits();
  RandomStream::Block draw{};
  uint64_t drawn = UINT64_MAX;
  for (uint64_t c = 0; c < B; ++c) {
    if (!filter.all && !filter.allows(digits[c])) continue;
    Coord child{};
    for (int d = 0; d < 3; ++d) child[d] = d < l.dimension ? parent[d] * l.base + digits[c][d] : 0;
    const Threshold t = threshold_of(field.survival(l, w.stage, child, w.product) / before);
    bool survives = t.certain;
    if (!survives && t.value != 0) {
      const uint64_t at = path * B + c;
      if (at >> 4 != drawn) {
        draw = w.rng.draw(at >> 4, root, w.curd, w.stage, DrawKind::survival, 0);
        drawn = at >> 4;
      }
      const unsigned byte = static_cast<unsigned>(at & 15);
      const uint32_t mine = draw[byte / 4] >> (8 * (byte % 4)) & 0xff;
      const auto top = static_cast<uint32_t>(t.value >> 56);
      survives = mine < top;
      if (mine == top && (t.value & kLow56) != 0) {
        const auto tie = w.rng.draw(at, root, w.curd, w.stage, DrawKind::tie_break, 0);
        survives = (RandomStream::high_word(tie) >> 8) < (t.value & kLow56);
      }
    }
    if (survives) children.set(index * B + c);
  }
}

void canonical_or_exact_stage(const StageWork& w, const Bitset& parents, Bitset& children) {
  const uint64_t B = w.children;
  auto run = [&](uint64_t begin, uint64_t end) {
    if (w.density) {
      for_each_parent(w, parents, begin, end, [&](uint64_t i, uint64_t path, uint32_t code) {
        density_children(w, i, path, code, children);
      });
    } else if (w.mode == Mode::exact) {
      const uint64_t keep = w.p.round_times(B);
      std::vector<std::pair<uint64_t, uint32_t>> keys;
      std::vector<uint64_t> chosen;
      for_each_parent(w, parents, begin, end, [&](uint64_t i, uint64_t path, uint32_t code) {
        const ChildFilter filter = filter_children(w, i);
        exact_children(w, path, code, keep, keys, chosen);
        for (uint64_t c = 0; c < B; c += 64) {
          const unsigned count = static_cast<unsigned>(std::min<uint64_t>(64, B - c));
          uint64_t bits = chosen[c / 64];
          if (bits) bits &= allowed_bits(w, filter, c, count);
          if (bits) children.or_bits(i * B + c, bits, count);
        }
      });
    } else if (w.p.certain()) {
      for_each_parent(w, parents, begin, end, [&](uint64_t i, uint64_t, uint32_t) {
        const ChildFilter filter = filter_children(w, i);
        for (uint64_t c = 0; c < B; c += 64) {
          const unsigned count = static_cast<unsigned>(std::min<uint64_t>(64, B - c));
          children.or_bits(i * B + c, allowed_bits(w, filter, c, count), count);
        }
      });
    } else if (w.p.threshold() != 0) {
      SurvivalBatch batch(w, children);
      for_each_parent(w, parents, begin, end,
                      [&](uint64_t i, uint64_t path, uint32_t code) { batch.add(i, path, code); });
    }
  };
  in_parent_tasks(parents.size, run);
}

// Quota mode: of all candidates (children of survivors inside the field), exactly `target`
// survive: those with the smallest (key, bit index) (smallest_keys.h).
void quota_stage(const StageWork& w, uint64_t target, const Bitset& parents, Bitset& children) {
  const uint64_t B = w.children;
  auto for_each_candidate = [&](auto&& f) {
    for_each_parent(w, parents, 0, parents.size, [&](uint64_t i, uint64_t path, uint32_t code) {
      const ChildFilter filter = filter_children(w, i);
      for (uint64_t c = 0; c < B; ++c) {
        if (!filter.all && !filter.allows(w.index.child_digits()[c])) continue;
        const auto r = w.rng.draw(path * B + c, code, w.curd, w.stage, DrawKind::quota_key, 0);
        f(RandomStream::high_word(r), i * B + c);
      }
    });
  };
  choose_smallest_keys(target, for_each_candidate, [&](uint64_t bit) { children.set(bit); });
}

}  // namespace

namespace {

// A Markov curd's planes (markov_curdling.h), all stages.
void curdle_chain(const Design& design, size_t first, CurdField& out, const RandomStream& rng,
                  bool prune, const GenerateOptions& options, double& done) {
  const Lattice& lattice = design.lattice;
  const MarkovChain& chain = *design.curds[first].chain;
  const std::span<Curd> planes(out.curds.data() + first, static_cast<size_t>(chain.planes()));
  for (Curd& plane : planes) {
    plane.stages.resize(lattice.stages + 1);
    plane.stages[0].assign_zero(out.index.roots());
  }
  const MarkovWork work{
      out.index, out.generated, prune, lattice.mode, rng, static_cast<uint32_t>(first), chain};
  markov_roots(work, planes);
  const double total_work = static_cast<double>(design.curds.size() * lattice.stages);
  for (int k = 1; k <= lattice.stages; ++k) {
    stop_point_now();
    for (Curd& plane : planes)
      plane.stages[k].assign_zero(out.index.roots() * lattice.cells_per_root(k));
    markov_stage(work, k, planes, cells_meeting(lattice, k, out.generated));
    done += static_cast<double>(planes.size());
    if (options.progress) options.progress(done / total_work);
  }
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
    const unsigned __int128 g =
        std::gcd(static_cast<uint64_t>(num % den), static_cast<uint64_t>(den));
    if (g > 1) num /= g, den /= g;
    if (num >> 100 || den >> 62) exact = false;
  }
  if (exact) return static_cast<uint64_t>((2 * num + den) / (2 * den));
  return static_cast<uint64_t>(
      std::floor(static_cast<double>(cells) * survival_probability(p, stage) + 0.5));
}

Box generation_box(const Design& design, const Box& view) {
  return design.lattice.mode == Mode::quota ? design.field : view;
}

uint64_t estimate_memory(const Design& design, const Box& box) {
  // Counted without building anything (a deep lattice's index tables alone can be gigabytes),
  // in 128 bits so that no product wraps; saturates at 2^64 - 1.
  const Lattice& l = design.lattice;
  const unsigned __int128 roots = cells_meeting(l, 0, box);
  unsigned __int128 words = 0;
  for (int k = 0; k <= l.stages; ++k) words += (roots * l.cells_per_root(k) + 63) / 64;
  const unsigned __int128 bytes = words * 8 * design.curds.size() + CellIndex::table_bytes(l);
  return bytes > UINT64_MAX ? UINT64_MAX : static_cast<uint64_t>(bytes);
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
      throw ResourceLimitError(
          "generating " + std::to_string(box.cells()) + " cells x " +
          std::to_string(design.curds.size()) + " curds needs about " + human_bytes(need) +
          ", above the memory limit of " + human_bytes(options.max_memory_bytes) +
          "; use a smaller field, window or fewer stages" +
          (options.memory_limit_hint.empty() ? "" : ", or " + options.memory_limit_hint));
  }
  // The index tables depend only on the lattice and the box: keep them across seeds.
  const Lattice& had = out.index.lattice();
  if (!(had.base == lattice.base && had.dimension == lattice.dimension &&
        had.stages == lattice.stages && out.generated == box && out.index.roots() > 0 &&
        !out.curds.empty()))
    out.index = CellIndex(lattice, box);
  out.generated = box;
  out.seed = seed;
  out.curds.resize(design.curds.size());

  const RandomStream rng(seed);
  const bool prune = !(box == out.index.covered_cells());
  const double total_work = static_cast<double>(design.curds.size() * lattice.stages);
  double done = 0;
  for (size_t c = 0; c < design.curds.size(); ++c) {
    if (design.curds[c].chain) {
      if (design.curds[c].plane == 0) curdle_chain(design, c, out, rng, prune, options, done);
      continue;
    }
    Curd& curd = out.curds[c];
    curd.stages.resize(lattice.stages + 1);
    curd.stages[0].assign_zero(out.index.roots());
    for (uint64_t r = 0; r < out.index.roots(); ++r) curd.stages[0].set(r);
    for (int k = 1; k <= lattice.stages; ++k) {
      stop_point_now();  // a stage of a large field takes seconds: a caller may stop between
      curd.stages[k].assign_zero(out.index.roots() * lattice.cells_per_root(k));
      const StageWork work{out.index,
                           box,
                           prune,
                           lattice.mode,
                           rng,
                           static_cast<uint32_t>(c),
                           k,
                           design.curds[c].probabilities[k - 1],
                           lattice.children(),
                           design.curds[c].density ? &*design.curds[c].density : nullptr,
                           survival_probability(design.curds[c].probabilities, k - 1),
                           survival_probability(design.curds[c].probabilities, k)};
      if (lattice.mode == Mode::quota)
        quota_stage(work,
                    quota_target(design.curds[c].probabilities, k, cells_meeting(lattice, k, box)),
                    curd.stages[k - 1], curd.stages[k]);
      else
        canonical_or_exact_stage(work, curd.stages[k - 1], curd.stages[k]);
      if (options.progress) options.progress(++done / total_work);
    }
  }
}

}  // namespace curdle
