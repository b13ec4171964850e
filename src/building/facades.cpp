#include "building/facades.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "curdle/error.h"
#include "layout/contour.h"
#include "layout/zone.h"

namespace curdle {
namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void refuse(const std::string& what, const char* key = "plan") {
  SourceLocation where;
  where.key = key;
  throw InputError(where, what);
}

// The edge's length along the wall, and the direction its outer face looks (plan radians): for
// an anticlockwise plan the outside is on the right of the edge, at its middle for an arc.
struct EdgeShape {
  double length = 0;
  double outward = 0;
};

EdgeShape edge_shape(const ContourVertex& a, const ContourVertex& b) {
  if (a.bulge == 0) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    return {std::hypot(dx, dy), std::atan2(-dx, dy)};  // the right-hand normal
  }
  const Arc arc = arc_between(a, b);
  const double middle = arc.start_angle() + arc.sweep / 2;
  // Anticlockwise (bulge > 0) the arc bows out to the right of the chord: its outer face looks
  // away from the centre; a clockwise arc bows in, and its outer face looks towards it.
  return {arc.radius * std::fabs(arc.sweep), a.bulge > 0 ? middle : middle + kPi};
}

// The edge's direction (plan radians) where it leaves `a` (at_end false) or reaches `b`.
double tangent(const ContourVertex& a, const ContourVertex& b, bool at_end) {
  if (a.bulge == 0) return std::atan2(b.y - a.y, b.x - a.x);
  const Arc arc = arc_between(a, b);
  const std::array<double, 2>& p = at_end ? arc.to : arc.from;
  const double radial = std::atan2(p[1] - arc.centre[1], p[0] - arc.centre[0]);
  return radial + (arc.sweep > 0 ? kPi / 2 : -kPi / 2);
}

// Plan radians (x east, y north, anticlockwise from east) to a bearing, clockwise from north.
double bearing_of(double radians) {
  double b = 90 - radians * 180 / kPi;
  b = std::fmod(b, 360);
  return b < 0 ? b + 360 : b;
}

// Whether segments ab and cd cross or touch (other than sharing nothing).
bool segments_cross(const std::array<double, 2>& a, const std::array<double, 2>& b,
                    const std::array<double, 2>& c, const std::array<double, 2>& d) {
  auto side = [](const std::array<double, 2>& p, const std::array<double, 2>& q,
                 const std::array<double, 2>& r) {
    const double x = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    return x > 0 ? 1 : x < 0 ? -1 : 0;
  };
  return side(a, b, c) * side(a, b, d) <= 0 && side(c, d, a) * side(c, d, b) <= 0;
}

// The turn from the direction `arriving` to `leaving`, degrees in (-180, 180]: positive
// anticlockwise, which on an anticlockwise plan is an outer corner.
double turn_between(double arriving, double leaving) {
  double t = std::remainder(leaving - arriving, 2 * kPi) * 180 / kPi;
  return t <= -180 ? t + 360 : t;
}

// The façade on the edge from a to b (plan edge `index`), starting `along` the strip, named by
// the compass point it faces (numbered from the second facing the same way).
Facade facade_on(const ContourVertex& a, const ContourVertex& b, size_t index, double along,
                 double shortest, const char* key, std::map<std::string, int>& named) {
  const EdgeShape shape = edge_shape(a, b);
  if (shape.length < shortest)
    refuse(fmt::format("edge {} is {:g} mm long, shorter than one unit ({:g} mm)", index,
                       shape.length, shortest),
           key);
  Facade f;
  f.index = index;
  f.from = {a.x, a.y};
  f.to = {b.x, b.y};
  f.bulge = a.bulge;
  f.length = shape.length;
  f.start = along;
  f.facing = bearing_of(shape.outward);
  const std::string point = compass_point(f.facing);
  const int n = ++named[point];
  f.name = n == 1 ? point : point + std::to_string(n);
  return f;
}

}  // namespace

std::string compass_point(double bearing) {
  static const char* const kPoints[8] = {"N", "NE", "E", "SE", "S", "SW", "W", "NW"};
  const int k = static_cast<int>(std::floor(std::fmod(bearing + 22.5, 360.0) / 45));
  return kPoints[(k % 8 + 8) % 8];
}

std::vector<Facade> unroll_plan(const Contour& given, size_t start, double shortest) {
  if (given.size() < 3) refuse("needs at least three vertices: a closed plan, anticlockwise");
  if (start >= given.size())
    refuse(fmt::format("start must be a vertex of the plan, 0 to {}", given.size() - 1));
  Contour plan = given;
  if (!is_simple(flatten(plan, 1.0)))
    refuse(
        "crosses itself: a building's plan is one closed outline whose edges meet only at "
        "its corners");
  for (const ContourVertex& v : plan)
    if (std::fabs(v.bulge) >= 1)
      refuse("has an arc of half a turn or more on one edge: split it at a vertex");
  // Anticlockwise, the outside on the right of every edge.
  if (signed_area(flatten(plan, 1.0)) < 0) {
    Contour reversed;
    for (size_t i = plan.size(); i-- > 0;) {
      const ContourVertex& to = plan[i];
      const ContourVertex& from = plan[(i + plan.size() - 1) % plan.size()];
      reversed.push_back({to.x, to.y, -from.bulge});
    }
    plan = reversed;
    start = plan.size() - 1 - start;  // the same corner, counted the other way
  }
  std::vector<Facade> out;
  std::map<std::string, int> named;
  double along = 0;
  for (size_t k = 0; k < plan.size(); ++k) {
    const size_t i = (start + k) % plan.size();
    const ContourVertex& a = plan[i];
    const ContourVertex& b = plan[(i + 1) % plan.size()];
    Facade f = facade_on(a, b, i, along, shortest, "plan", named);
    // The turn at its end, from this edge's direction to the next's: left (anticlockwise) is
    // an outer corner, right an inner one.
    const ContourVertex& c = plan[(i + 2) % plan.size()];
    const double arriving = tangent(a, b, true), leaving = tangent(b, c, false);
    f.turn_at_end = turn_between(arriving, leaving);
    along += f.length;
    out.push_back(std::move(f));
  }
  return out;
}

double strip_length(const std::vector<Facade>& facades) {
  return facades.empty() ? 0 : facades.back().start + facades.back().length;
}

}  // namespace curdle

namespace curdle {

std::vector<Facade> unroll_path(const Contour& path, double shortest) {
  if (path.size() < 2) refuse("needs at least two vertices: [[x, y], [x, y, bulge], ...]", "path");
  for (size_t i = 0; i + 1 < path.size(); ++i)
    if (std::fabs(path[i].bulge) >= 1)
      refuse("has an arc of half a turn or more on one edge: split it at a vertex", "path");
  std::vector<Facade> out;
  std::map<std::string, int> named;
  double along = 0;
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const ContourVertex& a = path[i];
    const ContourVertex& b = path[i + 1];
    Facade f = facade_on(a, b, i, along, shortest, "path", named);
    if (i + 2 < path.size())
      f.turn_at_end = turn_between(tangent(a, b, true), tangent(b, path[i + 2], false));
    f.last_of_path = i + 2 == path.size();
    along += f.length;
    out.push_back(std::move(f));
  }
  // A wall that meets itself is no wall: its faces would run through each other.
  Polygon line;
  for (const Facade& f : out) line.push_back(f.from);
  line.push_back(out.back().to);
  for (size_t i = 0; i + 1 < line.size(); ++i)
    for (size_t j = i + 2; j + 1 < line.size(); ++j)
      if (segments_cross(line[i], line[i + 1], line[j], line[j + 1]))
        refuse("crosses itself: a free-standing wall runs one way without meeting itself", "path");
  return out;
}

}  // namespace curdle
