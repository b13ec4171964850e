#include "site/wide_polyline.h"

#include <array>
#include <cmath>
#include <optional>

namespace curdle::site {
namespace {

using Vec = std::array<double, 2>;

// A straight piece of the centre line with its widths at either end.
struct Piece {
  Vec a, b;
  double wa, wb;
};

Vec left_normal(const Piece& p) {
  const double l = std::hypot(p.b[0] - p.a[0], p.b[1] - p.a[1]);
  return {-(p.b[1] - p.a[1]) / l, (p.b[0] - p.a[0]) / l};
}

// Where the lines p + s u and q + t v meet, if they are not parallel.
std::optional<Vec> meet(const Vec& p, const Vec& u, const Vec& q, const Vec& v) {
  const double d = u[0] * v[1] - u[1] * v[0];
  if (std::fabs(d) < 1e-12 * std::hypot(u[0], u[1]) * std::hypot(v[0], v[1])) return std::nullopt;
  const double s = ((q[0] - p[0]) * v[1] - (q[1] - p[1]) * v[0]) / d;
  return Vec{p[0] + s * u[0], p[1] + s * u[1]};
}

// One side's edge (side +1 left, -1 right) of each piece, joined where neighbours turn.
std::vector<Vec> side(const std::vector<Piece>& pieces, double sign) {
  std::vector<Vec> out;
  auto edge = [&](const Piece& p) {
    const Vec n = left_normal(p);
    return std::array<Vec, 2>{
        Vec{p.a[0] + sign * n[0] * p.wa / 2, p.a[1] + sign * n[1] * p.wa / 2},
        Vec{p.b[0] + sign * n[0] * p.wb / 2, p.b[1] + sign * n[1] * p.wb / 2}};
  };
  out.push_back(edge(pieces.front())[0]);
  for (size_t i = 0; i + 1 < pieces.size(); ++i) {
    const auto e = edge(pieces[i]), f = edge(pieces[i + 1]);
    const Vec u{e[1][0] - e[0][0], e[1][1] - e[0][1]}, v{f[1][0] - f[0][0], f[1][1] - f[0][1]};
    const auto m = meet(e[0], u, f[0], v);
    const double half = std::max(pieces[i].wb, pieces[i + 1].wa) / 2;
    const Vec& joint = pieces[i].b;
    // A mitre past four half-widths from the joint (a turn sharper than about 29°) is bevelled.
    if (m && std::hypot((*m)[0] - joint[0], (*m)[1] - joint[1]) <= 4 * half + 1e-12) {
      out.push_back(*m);
    } else {
      out.push_back(e[1]);
      out.push_back(f[0]);
    }
  }
  out.push_back(edge(pieces.back())[1]);
  return out;
}

}  // namespace

Contour swept_outline(const std::vector<WideVertex>& vertices, double tolerance) {
  std::vector<Piece> pieces;
  bool wide = false;
  for (size_t i = 0; i + 1 < vertices.size(); ++i) {
    const WideVertex& s = vertices[i];
    const WideVertex& e = vertices[i + 1];
    wide = wide || s.start_width > 0 || s.end_width > 0;
    // The segment's centre line as chords, its width tapering along their length.
    const Contour segment{{s.x, s.y, s.bulge}, {e.x, e.y, 0}};
    const Polygon points =
        s.bulge != 0 ? flatten(segment, tolerance) : Polygon{{s.x, s.y}, {e.x, e.y}};
    double total = 0;
    for (size_t k = 1; k < points.size(); ++k)
      total += std::hypot(points[k][0] - points[k - 1][0], points[k][1] - points[k - 1][1]);
    double along = 0;
    for (size_t k = 1; k < points.size(); ++k) {
      const double l = std::hypot(points[k][0] - points[k - 1][0], points[k][1] - points[k - 1][1]);
      if (!(l > 0)) continue;
      const double w0 = s.start_width + (s.end_width - s.start_width) * along / total;
      along += l;
      const double w1 = s.start_width + (s.end_width - s.start_width) * along / total;
      pieces.push_back({points[k - 1], points[k], w0, w1});
    }
  }
  if (!wide || pieces.empty()) return {};
  const std::vector<Vec> left = side(pieces, 1), right = side(pieces, -1);
  Contour out;
  // Left edge forward, then the right edge back: counter-clockwise about the band.
  for (auto it = right.begin(); it != right.end(); ++it) out.push_back({(*it)[0], (*it)[1], 0});
  for (auto it = left.rbegin(); it != left.rend(); ++it) out.push_back({(*it)[0], (*it)[1], 0});
  return out;
}

}  // namespace curdle::site
