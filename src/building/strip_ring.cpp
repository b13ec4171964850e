#include "building/strip_ring.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace curdle {
namespace {

// How far `x` (cells) lies from the nearest multiple of `size`.
double from_boundary(double x, double size) {
  const double within = x - size * std::floor(x / size);
  return std::min(within, size - within);
}

}  // namespace

StripRing ring_round(double length, double pitch, int64_t root) {
  StripRing ring;
  const double roots = std::round(length / (pitch * static_cast<double>(root)));
  ring.columns = std::max<int64_t>(1, static_cast<int64_t>(roots)) * root;
  ring.cell = length / static_cast<double>(ring.columns);
  return ring;
}

void turn_ring(StripRing& ring, const std::vector<double>& corners, int base, int stages,
               std::optional<int64_t> given) {
  // Each coarse stage's cell size in field cells, the root's first; the finest stage's cells
  // are single cells, whose boundaries no corner can keep a cell from.
  std::vector<double> sizes;
  int64_t root = 1;
  for (int k = 0; k < stages; ++k) root *= base;
  for (int64_t s = root; s >= 2; s /= base) sizes.push_back(static_cast<double>(s));
  auto score = [&](int64_t phase) {
    int quiet = 0;
    double next = 0;  // the least distance at the first stage not kept quiet, as a share
    for (double size : sizes) {
      double least = size;
      for (double u : corners)
        least = std::min(least, from_boundary(u / ring.cell + static_cast<double>(phase), size));
      if (least < 1) {
        next = least;
        break;
      }
      ++quiet;
    }
    return std::pair<int, double>{quiet, next};
  };
  if (given) {
    ring.phase = *given;
    ring.quiet_stages = score(*given).first;
    return;
  }
  // Every phase of a root cell, or 4,096 spread over it where the root is larger (a lattice of
  // 8 stages of base 8 has 16.8 million cells a root).
  const int64_t step = std::max<int64_t>(1, (std::min(root, ring.columns) + 4095) / 4096);
  std::pair<int, double> best{-1, 0};
  for (int64_t phase = 0; phase < root && phase < ring.columns; phase += step) {
    const std::pair<int, double> s = score(phase);
    if (s > best) best = s, ring.phase = phase;
  }
  ring.quiet_stages = best.first;
}

int64_t ring_column(const StripRing& ring, double u) {
  const auto cell = static_cast<int64_t>(std::floor(u / ring.cell)) + ring.phase;
  const int64_t column = cell % ring.columns;
  return column < 0 ? column + ring.columns : column;
}

std::string ring_note(const StripRing& ring, double pitch, int64_t root, bool given) {
  const int64_t roots = ring.columns / root;
  std::string stages = ring.quiet_stages == 0 ? "no coarse stage"
                       : ring.quiet_stages == 1
                           ? "the root cells'"
                           : fmt::format("the root cells' and {} stage{} below",
                                         ring.quiet_stages - 1, ring.quiet_stages == 2 ? "" : "s");
  return fmt::format(
      "the field wraps round the building: {} root cell{} of {} cells, {:.1f} mm a cell along "
      "the strip (a unit's pitch is {:g} mm), so that its last cell meets its first as across "
      "any root boundary; turned {} cell{} {}, so that no corner lies within a cell of a "
      "boundary of {}{}",
      roots, roots == 1 ? "" : "s", root, ring.cell, pitch, ring.phase, ring.phase == 1 ? "" : "s",
      given ? "as layout.building.phase says" : "(layout.building.phase fixes it)", stages,
      ring.quiet_stages == 0 ? " (none could be kept)" : "");
}

}  // namespace curdle
