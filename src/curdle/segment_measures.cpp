#include "curdle/segment_measures.h"

#include <algorithm>
#include <array>
#include <cassert>

namespace curdle {

void SegmentMeasures::reset(const Design& design, const Box& view, std::vector<uint16_t> values) {
  base_ = design.lattice.base;
  stages_ = design.lattice.stages;
  dimension_ = design.lattice.dimension;
  curds_ = static_cast<int>(design.curds.size());
  view_ = view;
  width_ = view.size[0];
  height_ = dimension_ >= 2 ? view.size[1] : 1;
  assert(dimension_ <= 2 && values.size() == static_cast<size_t>(width_ * height_));
  values_ = std::move(values);
  const size_t selectors = (size_t{1} << curds_) + static_cast<size_t>(curds_);
  prefix_.resize(selectors);
  prefix_ready_.assign(selectors, false);
}

const std::vector<uint32_t>& SegmentMeasures::prefix(uint32_t selector) {
  std::vector<uint32_t>& p = prefix_[selector];
  if (prefix_ready_[selector]) return p;
  const uint32_t values = uint32_t{1} << curds_;
  const bool is_curd = selector >= values;
  const uint32_t bit = is_curd ? uint32_t{1} << (selector - values) : 0;
  const size_t stride = static_cast<size_t>(width_) + 1;
  p.assign(stride * static_cast<size_t>(height_ + 1), 0);
  for (int64_t y = 0; y < height_; ++y) {
    uint32_t row = 0;
    const uint16_t* v = values_.data() + y * width_;
    uint32_t* above = p.data() + static_cast<size_t>(y) * stride;
    uint32_t* here = above + stride;
    for (int64_t x = 0; x < width_; ++x) {
      row += is_curd ? (v[x] & bit) != 0 : v[x] == selector;
      here[x + 1] = above[x + 1] + row;
    }
  }
  prefix_ready_[selector] = true;
  return p;
}

uint64_t SegmentMeasures::sum(const std::vector<uint32_t>& p, const Box& s) const {
  const size_t stride = static_cast<size_t>(width_) + 1;
  const int64_t x0 = s.origin[0] - view_.origin[0], x1 = x0 + s.size[0];
  const int64_t y0 = dimension_ >= 2 ? s.origin[1] - view_.origin[1] : 0;
  const int64_t y1 = y0 + (dimension_ >= 2 ? s.size[1] : 1);
  auto at = [&](int64_t x, int64_t y) { return p[static_cast<size_t>(y) * stride + x]; };
  return at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0);
}

uint64_t SegmentMeasures::value_count(uint32_t value, const Box& segment) {
  return sum(prefix(value), segment);
}

uint64_t SegmentMeasures::curd_count(size_t curd, const Box& segment) {
  return sum(prefix((uint32_t{1} << curds_) + static_cast<uint32_t>(curd)), segment);
}

std::vector<uint64_t> SegmentMeasures::box_counts(size_t curd, const Box& segment) {
  const std::vector<uint32_t>& p = prefix((uint32_t{1} << curds_) + static_cast<uint32_t>(curd));
  std::vector<uint64_t> counts(static_cast<size_t>(stages_) + 1, 0);
  const int axes = dimension_ >= 2 ? 2 : 1;
  int64_t side = 1;
  for (int j = stages_; j >= 0; --j, side *= base_) {
    if (side == 1) {
      counts[static_cast<size_t>(j)] = sum(p, segment);
      continue;
    }
    // Aligned boxes of `side` cells meeting the segment, each clipped to it.
    std::array<int64_t, 2> first{0, 0}, last{0, 0};
    for (int a = 0; a < axes; ++a) {
      first[a] = segment.origin[a] / side;
      last[a] = (segment.origin[a] + segment.size[a] - 1) / side;
    }
    uint64_t n = 0;
    for (int64_t by = first[1]; by <= last[1]; ++by)
      for (int64_t bx = first[0]; bx <= last[0]; ++bx) {
        Box clip = segment;
        clip.origin[0] = std::max(segment.origin[0], bx * side);
        clip.size[0] =
            std::min(segment.origin[0] + segment.size[0], (bx + 1) * side) - clip.origin[0];
        if (axes == 2) {
          clip.origin[1] = std::max(segment.origin[1], by * side);
          clip.size[1] =
              std::min(segment.origin[1] + segment.size[1], (by + 1) * side) - clip.origin[1];
        }
        n += sum(p, clip) > 0;
      }
    counts[static_cast<size_t>(j)] = n;
  }
  return counts;
}

uint64_t SegmentMeasures::largest_cluster(uint32_t value, const Box& s) {
  const int64_t x0 = s.origin[0] - view_.origin[0], w = s.size[0];
  const int64_t y0 = dimension_ >= 2 ? s.origin[1] - view_.origin[1] : 0;
  const int64_t h = dimension_ >= 2 ? s.size[1] : 1;
  seen_.resize(values_.size(), 0);
  if (++stamp_ == 0) std::fill(seen_.begin(), seen_.end(), 0), stamp_ = 1;
  auto cell = [&](int64_t x, int64_t y) { return static_cast<uint32_t>(y * width_ + x); };
  uint64_t largest = 0;
  for (int64_t y = y0; y < y0 + h; ++y)
    for (int64_t x = x0; x < x0 + w; ++x) {
      const uint32_t start = cell(x, y);
      if (values_[start] != value || seen_[start] == stamp_) continue;
      seen_[start] = stamp_;
      queue_.assign(1, start);
      for (size_t head = 0; head < queue_.size(); ++head) {
        const int64_t cx = queue_[head] % width_, cy = queue_[head] / width_;
        auto visit = [&](int64_t nx, int64_t ny) {
          if (nx < x0 || nx >= x0 + w || ny < y0 || ny >= y0 + h) return;
          const uint32_t i = cell(nx, ny);
          if (values_[i] != value || seen_[i] == stamp_) return;
          seen_[i] = stamp_;
          queue_.push_back(i);
        };
        visit(cx - 1, cy), visit(cx + 1, cy), visit(cx, cy - 1), visit(cx, cy + 1);
      }
      largest = std::max<uint64_t>(largest, queue_.size());
    }
  return largest;
}

uint64_t SegmentMeasures::longest_run(uint32_t value, const Box& s) {
  const int64_t x0 = s.origin[0] - view_.origin[0], w = s.size[0];
  const int64_t y0 = dimension_ >= 2 ? s.origin[1] - view_.origin[1] : 0;
  const int64_t h = dimension_ >= 2 ? s.size[1] : 1;
  uint64_t longest = 0;
  for (int64_t y = y0; y < y0 + h; ++y) {
    uint64_t run = 0;
    for (int64_t x = x0; x < x0 + w; ++x) {
      run = values_[static_cast<size_t>(y * width_ + x)] == value ? run + 1 : 0;
      longest = std::max(longest, run);
    }
  }
  std::vector<uint64_t> runs(static_cast<size_t>(w), 0);
  for (int64_t y = y0; y < y0 + h; ++y)
    for (int64_t x = x0; x < x0 + w; ++x) {
      uint64_t& run = runs[static_cast<size_t>(x - x0)];
      run = values_[static_cast<size_t>(y * width_ + x)] == value ? run + 1 : 0;
      longest = std::max(longest, run);
    }
  return longest;
}

std::optional<double> SegmentMeasures::lacunarity(uint32_t value, const Box& s, int64_t box) {
  const int64_t bw = std::min(box, s.size[0]);
  const int64_t bh = dimension_ >= 2 ? std::min(box, s.size[1]) : 1;
  const std::vector<uint32_t>& p = prefix(value);
  double sum1 = 0, sum2 = 0, positions = 0;
  const int64_t ny = dimension_ >= 2 ? s.size[1] - bh + 1 : 1;
  for (int64_t j = 0; j < ny; ++j)
    for (int64_t i = 0; i + bw <= s.size[0]; ++i) {
      Box b = s;
      b.origin[0] = s.origin[0] + i, b.size[0] = bw;
      if (dimension_ >= 2) b.origin[1] = s.origin[1] + j, b.size[1] = bh;
      const double m = static_cast<double>(sum(p, b));
      sum1 += m, sum2 += m * m, positions += 1;
    }
  if (sum1 == 0) return std::nullopt;
  const double mean = sum1 / positions;
  return (sum2 / positions) / (mean * mean);
}

}  // namespace curdle
