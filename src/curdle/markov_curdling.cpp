#include "curdle/markov_curdling.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numeric>
#include <vector>

#include "curdle/child_filter.h"
#include "curdle/parent_tasks.h"
#include "curdle/philox_batch.h"
#include "curdle/smallest_keys.h"
#include "curdle/theory.h"

namespace curdle {
namespace {

constexpr uint64_t kLow56 = (uint64_t{1} << 56) - 1;
constexpr uint8_t kUndecided = 0xff;

// A row's states by the top byte of u: decided, or kUndecided when the byte ties with a
// boundary that has bits below its top byte (then the low 56 bits decide).
struct RowTable {
  StateBounds bounds;
  std::array<uint8_t, 256> by_byte{};
  bool all_dead = true;
};

RowTable row_table(const std::vector<Probability>& row) {
  RowTable t;
  t.bounds = state_bounds(row);
  for (size_t j = 1; j < row.size(); ++j) t.all_dead &= row[j].value() == 0;
  for (unsigned x = 0; x < 256; ++x) {
    uint8_t state = 0;
    for (size_t j = 0; j < t.bounds.bound.size(); ++j) {
      const uint64_t T = t.bounds.bound[j];
      if (t.bounds.whole[j] || x < (T >> 56)) {
        state = static_cast<uint8_t>(j + 1);
        break;
      }
      if (x == (T >> 56) && (T & kLow56) != 0) {
        state = kUndecided;
        break;
      }
    }
    t.by_byte[x] = state;
  }
  return t;
}

// The uniform of one draw site: its top byte from a survival byte, its low bits on demand.
uint32_t state_from_byte(const RowTable& t, uint32_t byte, const RandomStream& rng, uint64_t at,
                         uint32_t root, uint32_t curd, int stage) {
  const uint8_t s = t.by_byte[byte];
  if (s != kUndecided) return s;
  const auto tie = rng.draw(at, root, curd, static_cast<uint32_t>(stage), DrawKind::tie_break, 0);
  return t.bounds.state_of(uint64_t{byte} << 56 | RandomStream::high_word(tie) >> 8);
}

void set_state(std::span<Curd> planes, int stage, uint64_t bit, uint32_t state) {
  for (size_t p = 0; p < planes.size(); ++p)
    if (state >> p & 1) planes[p].stages[static_cast<size_t>(stage)].set(bit);
}

// Calls f(index, path, root code, state) for every parent in [begin, end) of stage k - 1 that
// can have living children: the living ones, and the dead too when the dead row revives.
template <class F>
void for_each_parent(const MarkovWork& w, std::span<const Curd> planes, int k, uint64_t begin,
                     uint64_t end, bool dead_too, F&& f) {
  const auto stage = static_cast<size_t>(k - 1);
  const uint64_t per_root = w.index.lattice().cells_per_root(k - 1);
  uint64_t root = UINT64_MAX, root_start = 0;
  uint32_t code = 0;
  for (uint64_t word = begin >> 6; word < (end + 63) >> 6; ++word) {
    uint64_t any = 0;
    std::array<uint64_t, 16> plane_words;  // only the planes' entries are read
    for (size_t p = 0; p < planes.size(); ++p) {
      plane_words[p] = planes[p].stages[stage].words[word];
      any |= plane_words[p];
    }
    uint64_t m = dead_too ? ~uint64_t{0} : any;
    const uint64_t lo = word << 6;
    if (lo < begin) m &= ~uint64_t{0} << (begin - lo);
    if (end - lo < 64) m &= (uint64_t{1} << (end - lo)) - 1;
    for (; m; m &= m - 1) {
      const unsigned bit = static_cast<unsigned>(std::countr_zero(m));
      const uint64_t i = lo + bit;
      if (root == UINT64_MAX || i >= root_start + per_root) {
        root = i / per_root;
        root_start = root * per_root;
        code = w.index.root_code(root);
      }
      uint32_t state = 0;
      for (size_t p = 0; p < planes.size(); ++p)
        state |= static_cast<uint32_t>(plane_words[p] >> bit & 1) << p;
      f(i, i - root_start, code, state);
    }
  }
}

// Canonical stage for a batch of parents: their survival draws made at once, eight lanes at a
// time (philox_batch.h), then each child's state from its byte, and each parent's children
// written a word per plane. The same draws as one at a time: neighbouring parents share a draw
// when b^E < 16.
class CanonicalBatch {
 public:
  static constexpr size_t kParents = 64;

  CanonicalBatch(const MarkovWork& w, int k, std::span<Curd> planes,
                 const std::vector<RowTable>& rows)
      : w_(w), k_(k), planes_(planes), rows_(rows), B_(w.index.lattice().children()) {
    const size_t most = (kParents * (B_ / 16 + 2) + 7) / 8 * 8;
    for (auto* v : {&w0_, &w1_, &w2_, &w3_, &roots_}) v->resize(most);
    blocks_.resize(most);
    bytes_.resize(16 * most);
  }
  ~CanonicalBatch() { flush(); }

  void add(uint64_t index, uint64_t path, uint32_t root, uint32_t state) {
    if (rows_[state].all_dead) return;
    parents_[count_++] = Parent{index, path, root, state, 0};
    if (count_ == kParents) flush();
  }

  void flush() {
    if (count_ == 0) return;
    const uint32_t tag =
        RandomStream::tag(w_.curd, static_cast<uint32_t>(k_), DrawKind::survival, 0);
    size_t n = 0;
    for (size_t p = 0; p < count_; ++p) {
      Parent& parent = parents_[p];
      const uint64_t first = parent.path * B_ >> 4, last = (parent.path * B_ + B_ - 1) >> 4;
      for (uint64_t b = first; b <= last; ++b) {
        const bool shared = n > 0 && blocks_[n - 1] == b && w2_[n - 1] == parent.root;
        if (b == first) parent.first_block = n - (shared ? 1 : 0);
        if (shared) continue;
        blocks_[n] = b;
        w0_[n] = static_cast<uint32_t>(b);
        w1_[n] = static_cast<uint32_t>(b >> 32);
        w2_[n] = parent.root;
        w3_[n++] = tag;
      }
    }
    std::copy(w2_.begin(), w2_.begin() + static_cast<int64_t>(n), roots_.begin());
    const size_t lanes = (n + 7) / 8 * 8;
    for (size_t i = n; i < lanes; ++i) w0_[i] = w1_[i] = w2_[i] = w3_[i] = 0;
    philox_in_place(w0_.data(), w1_.data(), w2_.data(), w3_.data(), lanes, w_.rng.key(0),
                    w_.rng.key(1));
    // Byte 4 w + q of a draw is byte q of word w: little-endian words side by side.
    for (size_t i = 0; i < n; ++i) {
      const std::array<uint32_t, 4> words{w0_[i], w1_[i], w2_[i], w3_[i]};
      for (unsigned b = 0; b < 16; ++b)
        bytes_[16 * i + b] = static_cast<uint8_t>(words[b / 4] >> (8 * (b % 4)));
    }
    for (size_t p = 0; p < count_; ++p) write_children(parents_[p]);
    count_ = 0;
  }

 private:
  struct Parent {
    uint64_t index, path;
    uint32_t root, state;
    size_t first_block;
  };

  // With the count of planes known at compile time for chains of up to eight states (one to
  // three planes), the per-child loops over the planes unroll.
  void write_children(const Parent& parent) {
    switch (planes_.size()) {
      case 1:
        return write_children_of<1>(parent);
      case 2:
        return write_children_of<2>(parent);
      case 3:
        return write_children_of<3>(parent);
      default:
        return write_children_of<0>(parent);
    }
  }

  // P planes, or planes_.size() when P is 0.
  template <size_t P>
  void write_children_of(const Parent& parent) {
    const size_t planes = P ? P : planes_.size();
    const RowTable& t = rows_[parent.state];
    const ChildFilter filter =
        w_.prune ? children_in_box(w_.index, w_.box, k_, parent.index) : ChildFilter{};
    const auto& digits = w_.index.child_digits();
    const uint64_t first_at = parent.path * B_;
    for (uint64_t c0 = 0; c0 < B_; c0 += 64) {
      const auto count = static_cast<unsigned>(std::min<uint64_t>(64, B_ - c0));
      std::array<uint64_t, 16> bits;  // only the planes' entries: a whole clear costs more
      std::fill_n(bits.begin(), planes, uint64_t{0});
      for (unsigned c = 0; c < count; ++c) {
        const uint64_t at = first_at + c0 + c;
        if (!filter.all && !filter.allows(digits[c0 + c])) continue;
        const size_t block = parent.first_block + ((at >> 4) - (first_at >> 4));
        const uint8_t byte = bytes_[16 * block + (at & 15)];
        uint32_t s = t.by_byte[byte];
        if (s == kUndecided) s = state_from_byte(t, byte, w_.rng, at, roots_[block], w_.curd, k_);
        for (size_t p = 0; p < planes; ++p) bits[p] |= uint64_t{s >> p & 1} << c;
      }
      for (size_t p = 0; p < planes; ++p)
        if (bits[p])
          planes_[p].stages[static_cast<size_t>(k_)].or_bits(parent.index * B_ + c0, bits[p],
                                                             count);
    }
  }

  const MarkovWork& w_;
  int k_;
  std::span<Curd> planes_;
  const std::vector<RowTable>& rows_;
  uint64_t B_;
  std::vector<uint32_t> w0_, w1_, w2_, w3_, roots_;
  std::vector<uint64_t> blocks_;
  std::vector<uint8_t> bytes_;
  std::array<Parent, kParents> parents_;
  size_t count_ = 0;
};

void canonical_stage(const MarkovWork& w, int k, std::span<Curd> planes,
                     const std::vector<RowTable>& rows) {
  const bool dead_too = !rows[0].all_dead;
  in_parent_tasks(planes[0].stages[static_cast<size_t>(k - 1)].size,
                  [&](uint64_t begin, uint64_t end) {
                    CanonicalBatch batch(w, k, planes, rows);
                    for_each_parent(w, planes, k, begin, end, dead_too,
                                    [&](uint64_t i, uint64_t path, uint32_t code, uint32_t state) {
                                      batch.add(i, path, code, state);
                                    });
                  });
}

void exact_stage(const MarkovWork& w, int k, std::span<Curd> planes) {
  const uint64_t B = w.index.lattice().children();
  const auto& digits = w.index.child_digits();
  const size_t S = w.chain.living();
  std::vector<std::vector<uint64_t>> counts(S + 1);  // per parent state, per living state
  for (size_t i = 0; i <= S; ++i)
    for (size_t j = 1; j <= S; ++j) counts[i].push_back(w.chain.row(k, i)[j].round_times(B));
  const bool dead_too = w.chain.revives(k);
  in_parent_tasks(
      planes[0].stages[static_cast<size_t>(k - 1)].size, [&](uint64_t begin, uint64_t end) {
        std::vector<std::pair<uint64_t, uint32_t>> keys(B);
        for_each_parent(
            w, planes, k, begin, end, dead_too,
            [&](uint64_t i, uint64_t path, uint32_t code, uint32_t state) {
              for (uint64_t j = 0; 2 * j < B; ++j) {
                const auto r = w.rng.draw(path, code, w.curd, static_cast<uint32_t>(k),
                                          DrawKind::exact_key, static_cast<uint32_t>(j));
                keys[2 * j] = {RandomStream::high_word(r), static_cast<uint32_t>(2 * j)};
                if (2 * j + 1 < B)
                  keys[2 * j + 1] = {RandomStream::low_word(r), static_cast<uint32_t>(2 * j + 1)};
              }
              const uint64_t living =
                  std::accumulate(counts[state].begin(), counts[state].end(), uint64_t{0});
              if (living == 0) return;
              if (living < B)
                std::nth_element(keys.begin(), keys.begin() + (living - 1), keys.end());
              std::sort(keys.begin(), keys.begin() + living);
              const ChildFilter filter =
                  w.prune ? children_in_box(w.index, w.box, k, i) : ChildFilter{};
              uint64_t next = 0;
              for (size_t s = 1; s <= S; ++s)
                for (uint64_t n = 0; n < counts[state][s - 1]; ++n, ++next) {
                  const uint32_t c = keys[next].second;
                  if (filter.all || filter.allows(digits[c]))
                    set_state(planes, k, i * B + c, static_cast<uint32_t>(s));
                }
            });
      });
}

std::vector<uint64_t> quota_stage(const MarkovWork& w, int k, std::span<Curd> planes,
                                  uint64_t field_cells) {
  const uint64_t B = w.index.lattice().children();
  const auto& digits = w.index.child_digits();
  const size_t S = w.chain.living();
  const std::vector<double> share = state_shares(w.chain, k);
  const bool dead_too = w.chain.revives(k);
  Bitset taken;
  taken.assign_zero(planes[0].stages[static_cast<size_t>(k)].size);
  std::vector<uint64_t> short_of(S, 0);
  double cumulative = 0;
  uint64_t given = 0;
  bool fell_short = false;
  for (size_t j = 1; j <= S; ++j) {
    cumulative += share[j];
    const auto total =
        static_cast<uint64_t>(std::floor(static_cast<double>(field_cells) * cumulative + 0.5));
    const uint64_t target = total > given ? total - given : 0;
    given += target;
    auto for_each_candidate = [&](auto&& f) {
      for_each_parent(w, planes, k, 0, planes[0].stages[static_cast<size_t>(k - 1)].size, dead_too,
                      [&](uint64_t i, uint64_t path, uint32_t code, uint32_t state) {
                        const double p = w.chain.row(k, state)[j].value();
                        if (!(p > 0)) return;
                        const ChildFilter filter =
                            w.prune ? children_in_box(w.index, w.box, k, i) : ChildFilter{};
                        for (uint64_t c = 0; c < B; ++c) {
                          if (!filter.all && !filter.allows(digits[c])) continue;
                          if (taken.test(i * B + c)) continue;
                          const auto r =
                              w.rng.draw(path * B + c, code, w.curd, static_cast<uint32_t>(k),
                                         DrawKind::quota_key, static_cast<uint32_t>(j - 1));
                          // u in (0, 1]; its weighted key, order kept by a positive double's bits
                          const double u =
                              (static_cast<double>(RandomStream::high_word(r) >> 11) + 1) * 0x1p-53;
                          f(std::bit_cast<uint64_t>(-std::log1p(-u + 0x1p-54) / p), i * B + c);
                        }
                      });
    };
    const uint64_t chosen = choose_smallest_keys(target, for_each_candidate, [&](uint64_t bit) {
      taken.set(bit);
      set_state(planes, k, bit, static_cast<uint32_t>(j));
    });
    short_of[j - 1] = target - chosen;
    fell_short |= chosen < target;
  }
  return fell_short ? short_of : std::vector<uint64_t>{};
}

}  // namespace

void markov_roots(const MarkovWork& w, std::span<Curd> planes) {
  const RowTable t = row_table(w.chain.start);
  for (uint64_t r = 0; r < w.index.roots(); ++r) {
    const uint32_t code = w.index.root_code(r);
    const auto draw = w.rng.draw(0, code, w.curd, 0, DrawKind::survival, 0);
    const uint32_t s = state_from_byte(t, draw[0] & 0xff, w.rng, 0, code, w.curd, 0);
    if (s) set_state(planes, 0, r, s);
  }
}

std::vector<uint64_t> markov_stage(const MarkovWork& w, int stage, std::span<Curd> planes,
                                   uint64_t field_cells) {
  if (w.mode == Mode::quota) return quota_stage(w, stage, planes, field_cells);
  if (w.mode == Mode::exact) {
    exact_stage(w, stage, planes);
    return {};
  }
  std::vector<RowTable> rows;
  for (size_t i = 0; i <= w.chain.living(); ++i) rows.push_back(row_table(w.chain.row(stage, i)));
  canonical_stage(w, stage, planes, rows);
  return {};
}

}  // namespace curdle
