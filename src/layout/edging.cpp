#include "layout/edging.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "layout/zone.h"

namespace curdle {
namespace {

// A segment on its line: the line's direction (as an angle) and distance from the origin, both
// rounded so that two pieces' edges on one line meet, and the segment's extent along it.
struct LineKey {
  int64_t angle = 0, offset = 0;
  uint32_t group = 0;
  auto operator<=>(const LineKey&) const = default;
};
struct Span {
  double from = 0, to = 0;
  size_t piece = 0;
};

}  // namespace

std::vector<Ring> piece_rings(const Element& e) {
  if (e.outline) return e.outline->rings;
  std::vector<Ring> rings;
  for (const Rect& r : e.shape) rings.push_back(rect_polygon(r));
  return rings;
}

std::vector<double> unshared_edge_lengths(const std::vector<EdgedPiece>& pieces) {
  std::map<LineKey, std::vector<Span>> lines;
  for (size_t p = 0; p < pieces.size(); ++p)
    for (const Ring& ring : pieces[p].rings)
      for (size_t i = 0; i < ring.size(); ++i) {
        const auto& a = ring[i];
        const auto& b = ring[(i + 1) % ring.size()];
        double dx = b[0] - a[0], dy = b[1] - a[1];
        const double length = std::hypot(dx, dy);
        if (length < 1e-9) continue;
        dx /= length, dy /= length;
        if (dx < -1e-12 || (std::abs(dx) <= 1e-12 && dy < 0)) dx = -dx, dy = -dy;
        // Both directions of a line share one key: the angle in [0, pi), and the signed
        // distance of the line from the origin.
        const LineKey key{std::llround(std::atan2(dy, dx) * 1e7),
                          std::llround((a[0] * dy - a[1] * dx) * 100), pieces[p].group};
        const double ta = a[0] * dx + a[1] * dy, tb = b[0] * dx + b[1] * dy;
        lines[key].push_back({std::min(ta, tb), std::max(ta, tb), p});
      }
  // Along each line, a stretch covered by one edge is unshared; by two, the pieces on either
  // side are of one group and join there (pieces do not overlap, so no more than two cover it).
  std::vector<double> unshared(pieces.size(), 0.0);
  for (auto& [key, spans] : lines) {
    std::vector<std::tuple<double, bool, size_t>> events;  // position, starts, span
    for (size_t s = 0; s < spans.size(); ++s) {
      events.emplace_back(spans[s].from, true, s);
      events.emplace_back(spans[s].to, false, s);
    }
    std::sort(events.begin(), events.end());
    std::vector<size_t> open;
    double at = 0;
    for (const auto& [position, starts, s] : events) {
      if (open.size() == 1) unshared[spans[open.front()].piece] += position - at;
      at = position;
      if (starts)
        open.push_back(s);
      else
        open.erase(std::find(open.begin(), open.end(), s));
    }
  }
  return unshared;
}

}  // namespace curdle
