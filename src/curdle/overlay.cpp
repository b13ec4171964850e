#include "curdle/overlay.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <bit>

#include "curdle/markov.h"
#include "curdle/theory.h"
#include "curdle/view_cells.h"

namespace curdle {

std::vector<uint64_t> value_counts(const CurdField& field) {
  const size_t n = field.curds.size();
  const size_t values = size_t{1} << n;
  if (n == 0) return std::vector<uint64_t>(1, field.generated.cells());
  const size_t words = field.finest(0).words.size();
  std::vector<const uint64_t*> curd(n);
  for (size_t i = 0; i < n; ++i) curd[i] = field.finest(i).words.data();
  // counts[0] holds the cells where any curd survived until the end.
  auto count_range = [&](size_t begin, size_t end, std::vector<uint64_t>& counts) {
    for (size_t w = begin; w < end; ++w) {
      uint64_t any = 0;
      for (size_t i = 0; i < n; ++i) any |= curd[i][w];
      if (!any) continue;
      counts[0] += std::popcount(any);
      if (n <= 4) {
        // Word-parallel: the cells of value v are those where each curd matches its bit of v.
        for (uint32_t v = 1; v < values; ++v) {
          uint64_t m = any;
          for (size_t i = 0; i < n; ++i) m &= (v >> i & 1) ? curd[i][w] : ~curd[i][w];
          counts[v] += std::popcount(m);
        }
      } else {
        for (uint64_t m = any; m; m &= m - 1) {
          const unsigned bit = std::countr_zero(m);
          uint32_t v = 0;
          for (size_t i = 0; i < n; ++i) v |= static_cast<uint32_t>(curd[i][w] >> bit & 1) << i;
          ++counts[v];
        }
      }
    }
  };
  std::vector<uint64_t> counts(values, 0);
  if (words < (1u << 16)) {
    count_range(0, words, counts);
  } else {
    tbb::combinable<std::vector<uint64_t>> partial(
        [values] { return std::vector<uint64_t>(values, 0); });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, words, 1 << 14),
                      [&](const tbb::blocked_range<size_t>& r) {
                        count_range(r.begin(), r.end(), partial.local());
                      });
    partial.combine_each([&](const std::vector<uint64_t>& p) {
      for (size_t v = 0; v < values; ++v) counts[v] += p[v];
    });
  }
  counts[0] = field.generated.cells() - counts[0];
  return counts;
}

CurdField restrict_to(const CurdField& field, const Box& view) {
  CurdField out = field;
  out.generated = view;
  const Lattice& l = field.index.lattice();
  for (Curd& curd : out.curds) {
    for (int k = 0; k <= l.stages; ++k) {
      Bitset& bits = curd.stages[k];
      const int64_t width = static_cast<int64_t>(l.side_in_cells(k));
      for_each_set(field.curds[&curd - out.curds.data()].stages[k], 0, bits.size, [&](uint64_t i) {
        const Coord c = field.index.decode(k, i);
        for (int d = 0; d < l.dimension; ++d) {
          const int64_t start = c[d] * width;
          if (start >= view.origin[d] + view.size[d] || start + width <= view.origin[d]) {
            bits.words[i >> 6] &= ~(uint64_t{1} << (i & 63));
            return;
          }
        }
      });
    }
  }
  return out;
}

std::vector<double> expected_value_shares(const Design& design) {
  const std::vector<CurdGroup> groups = curd_groups(design.curds);
  std::vector<std::vector<double>> chances;
  for (const CurdGroup& g : groups) {
    if (g.chain) {
      chances.push_back(state_shares(*g.chain, design.lattice.stages));
      chances.back().resize(size_t{1} << g.planes, 0.0);
    } else {
      const double P =
          survival_probability(design.curds[g.first].probabilities, design.lattice.stages);
      chances.push_back({1 - P, P});
    }
  }
  std::vector<double> shares(size_t{1} << design.curds.size(), 1.0);
  for (uint32_t v = 0; v < shares.size(); ++v)
    for (size_t g = 0; g < groups.size(); ++g) shares[v] *= chances[g][groups[g].state(v)];
  return shares;
}

std::string value_label(uint32_t value, const std::vector<CurdSpec>& curds) {
  std::string label;
  for (const CurdGroup& g : curd_groups(curds)) {
    const uint32_t state = g.state(value);
    if (state == 0) continue;
    if (!label.empty()) label += "+";
    label += g.chain ? g.chain->state_name(state) : curds[g.first].name;
  }
  return label.empty() ? "empty" : label;
}

void scan_rows(const CurdField& field, const Box& view,
               const std::function<void(int64_t, int64_t, std::span<const uint16_t>)>& row,
               const std::function<void(double)>& progress) {
  const ViewCells cells(field, view);
  std::vector<uint16_t> values(view.size[0]);
  for (int64_t z = 0; z < view.size[2]; ++z)
    for (int64_t y = 0; y < view.size[1]; ++y) {
      const uint64_t row_start = cells.row(y, z);
      for (int64_t x = 0; x < view.size[0]; ++x)
        values[x] = static_cast<uint16_t>(field.value_of(cells.at(row_start, x)));
      row(view.origin[1] + y, view.origin[2] + z, values);
      if (progress && (y & 255) == 0)
        progress(static_cast<double>(z * view.size[1] + y) / (view.size[1] * view.size[2]));
    }
}

std::vector<uint16_t> values_in(const CurdField& field, const Box& view) {
  std::vector<uint16_t> values;
  values.reserve(view.cells());
  scan_rows(field, view, [&](int64_t, int64_t, std::span<const uint16_t> r) {
    values.insert(values.end(), r.begin(), r.end());
  });
  return values;
}

}  // namespace curdle
