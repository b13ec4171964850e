#include "export/ifc/ifc_geometry.h"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "curdle/palette.h"
#include "layout/zone.h"

namespace curdle {
namespace {

using step::real;
using step::ref;

// Inner boundaries run clockwise, against the outer ring, as every reader expects of a void.
Ring clockwise(Ring ring) {
  if (signed_area(ring) > 0) std::reverse(ring.begin(), ring.end());
  return ring;
}

}  // namespace

Ring ifc_circle_ring(const Circle& c, double chord_tolerance) {
  const double r = c.d / 2, pi = 3.14159265358979323846;
  const double step = 2 * std::acos(std::max(-1.0, 1 - chord_tolerance / r));
  const int quarter = std::clamp(static_cast<int>(std::ceil(pi / 2 / step)), 2, 256);
  Ring ring;
  for (int k = 0; k < 4 * quarter; ++k) {
    const double a = pi / 2 * k / quarter;
    // The extremes exactly, not through sin and cos.
    const int q = k % quarter == 0 ? k / quarter : -1;
    const double dx = q == 0 ? r : q == 2 ? -r : 0, dy = q == 1 ? r : q == 3 ? -r : 0;
    ring.push_back(q < 0 ? std::array<double, 2>{c.cx + r * std::cos(a), c.cy + r * std::sin(a)}
                         : std::array<double, 2>{c.cx + dx, c.cy + dy});
  }
  return ring;
}

IfcGeometryWriter::IfcGeometryWriter(StepWriter& w, double chord_tolerance)
    : w_(w), chord_tolerance_(chord_tolerance) {
  const int64_t origin = point(0, 0, 0);
  z_ = direction(0, 0, 1);
  world_ = w_.add(FMT_COMPILE("IFCAXIS2PLACEMENT3D({},$,$)"), ref(origin));
}

int64_t IfcGeometryWriter::point(double x, double y) {
  return w_.add(FMT_COMPILE("IFCCARTESIANPOINT(({},{}))"), real(x - local_[0]),
                real(y - local_[1]));
}
int64_t IfcGeometryWriter::point(double x, double y, double z) {
  return w_.add(FMT_COMPILE("IFCCARTESIANPOINT(({},{},{}))"), real(x), real(y), real(z));
}
int64_t IfcGeometryWriter::direction(double x, double y, double z) {
  return w_.add(FMT_COMPILE("IFCDIRECTION(({},{},{}))"), real(x), real(y), real(z));
}

int64_t IfcGeometryWriter::polyline(const Ring& ring) {
  std::vector<int64_t> points;
  for (const auto& v : ring) points.push_back(point(v[0], v[1]));
  points.push_back(points.front());
  return w_.add("IFCPOLYLINE(" + step_refs(points) + ")");
}

int64_t IfcGeometryWriter::point_list(const std::vector<std::array<double, 2>>& points) {
  std::string list = "IFCCARTESIANPOINTLIST2D((";
  list.reserve(list.size() + 48 * points.size());
  for (const auto& [x, y] : points) {
    list += '(';
    append_step_real(list, x);
    list += ',';
    append_step_real(list, y);
    list += "),";
  }
  list.back() = ')';
  list += ')';
  return w_.add(list);
}

int64_t IfcGeometryWriter::point_list_curve(const Ring& ring) {
  std::vector<std::array<double, 2>> points;
  points.reserve(ring.size() + 1);
  for (const auto& [x, y] : ring) points.push_back({x - local_[0], y - local_[1]});
  points.push_back(points.front());
  return w_.add(FMT_COMPILE("IFCINDEXEDPOLYCURVE({},$,.F.)"), ref(point_list(points)));
}

int64_t IfcGeometryWriter::contour_curve(const Contour& c) {
  std::vector<std::array<double, 2>> points{{c[0].x, c[0].y}};
  std::string segments;
  auto index_of = [&](double x, double y) {
    points.push_back({x, y});
    return points.size();
  };
  for (size_t i = 0; i < c.size(); ++i) {
    const size_t from = points.size();
    const ContourVertex& next = c[(i + 1) % c.size()];
    const size_t to = i + 1 < c.size() ? 0 : 1;  // the last edge closes on the first point
    if (!segments.empty()) segments += ',';
    if (c[i].bulge == 0) {
      const size_t end = to ? to : index_of(next.x, next.y);
      segments += fmt::format("IFCLINEINDEX(({},{}))", from, end);
      continue;
    }
    const Arc a = arc_between(c[i], next);
    const double mid = a.start_angle() + a.sweep / 2;
    const size_t middle =
        index_of(a.centre[0] + a.radius * std::cos(mid), a.centre[1] + a.radius * std::sin(mid));
    const size_t end = to ? to : index_of(next.x, next.y);
    segments += fmt::format("IFCARCINDEX(({},{},{}))", from, middle, end);
  }
  return w_.add(FMT_COMPILE("IFCINDEXEDPOLYCURVE({},({}),.F.)"), ref(point_list(points)), segments);
}

int64_t IfcGeometryWriter::shared_polyline(const Ring& ring) {
  std::vector<std::array<int64_t, 2>> shape;
  for (const auto& [x, y] : ring)
    shape.push_back({std::llround((x - local_[0]) * 1e6), std::llround((y - local_[1]) * 1e6)});
  auto it = shared_polylines_.find(shape);
  if (it != shared_polylines_.end()) return it->second;
  return shared_polylines_[std::move(shape)] = polyline(ring);
}

int64_t IfcGeometryWriter::rectangle(const Rect& r) {
  const int64_t at =
      w_.add(FMT_COMPILE("IFCAXIS2PLACEMENT2D({},$)"), ref(point(r.x + r.w / 2, r.y + r.h / 2)));
  return w_.add(FMT_COMPILE("IFCRECTANGLEPROFILEDEF(.AREA.,$,{},{},{})"), ref(at), real(r.w),
                real(r.h));
}

int64_t IfcGeometryWriter::circle(const Circle& c) {
  return w_.add(FMT_COMPILE("IFCARBITRARYCLOSEDPROFILEDEF(.AREA.,$,{})"),
                ref(polyline(ifc_circle_ring(c, chord_tolerance_))));
}

int64_t IfcGeometryWriter::part_profile(const Outline& part) {
  return profile_with_holes(part.rings.front(),
                            std::vector<Ring>(part.rings.begin() + 1, part.rings.end()));
}

int64_t IfcGeometryWriter::profile(const std::vector<Outline>& parts) {
  if (parts.size() == 1) return part_profile(parts.front());
  std::vector<int64_t> profiles;
  for (const Outline& part : parts) profiles.push_back(part_profile(part));
  return w_.add(FMT_COMPILE("IFCCOMPOSITEPROFILEDEF(.AREA.,$,{},$)"), step_refs(profiles));
}

int64_t IfcGeometryWriter::profile_with_holes(const Ring& outer, const std::vector<Ring>& holes) {
  const int64_t boundary = polyline(outer);
  if (holes.empty())
    return w_.add(FMT_COMPILE("IFCARBITRARYCLOSEDPROFILEDEF(.AREA.,$,{})"), ref(boundary));
  std::vector<int64_t> inner;
  for (const Ring& hole : holes) inner.push_back(point_list_curve(clockwise(hole)));
  return w_.add(FMT_COMPILE("IFCARBITRARYPROFILEDEFWITHVOIDS(.AREA.,$,{},{})"), ref(boundary),
                step_refs(inner));
}

int64_t IfcGeometryWriter::solid(int64_t profile, double base, double depth, const Rgb& colour) {
  const int64_t s = w_.add(FMT_COMPILE("IFCEXTRUDEDAREASOLID({},{},{},{})"), ref(profile),
                           ref(base_placement(base)), ref(z_), real(depth));
  w_.add(FMT_COMPILE("IFCSTYLEDITEM({},({}),$)"), ref(s), ref(style(colour)));
  return s;
}

int64_t IfcGeometryWriter::solid_placed(int64_t profile, int64_t position, double depth,
                                        const Rgb& colour) {
  const int64_t s = w_.add(FMT_COMPILE("IFCEXTRUDEDAREASOLID({},{},{},{})"), ref(profile),
                           ref(position), ref(z_), real(depth));
  w_.add(FMT_COMPILE("IFCSTYLEDITEM({},({}),$)"), ref(s), ref(style(colour)));
  return s;
}

int64_t IfcGeometryWriter::axes(const std::array<double, 3>& o, const std::array<double, 3>& z,
                                const std::array<double, 3>& x) {
  auto once = [&](const std::array<double, 3>& d) {
    auto it = directions_.find(d);
    return it != directions_.end() ? it->second : directions_[d] = direction(d[0], d[1], d[2]);
  };
  const int64_t axis = once(z), ref_direction = once(x);
  return w_.add(FMT_COMPILE("IFCAXIS2PLACEMENT3D({},{},{})"), ref(point(o[0], o[1], o[2])),
                ref(axis), ref(ref_direction));
}

int64_t IfcGeometryWriter::body(const std::vector<int64_t>& items) {
  const int64_t rep = w_.add(FMT_COMPILE("IFCSHAPEREPRESENTATION({},'Body','SweptSolid',{})"),
                             ref(body_), step_refs(items));
  return w_.add(FMT_COMPILE("IFCPRODUCTDEFINITIONSHAPE($,$,({}))"), ref(rep));
}

int64_t IfcGeometryWriter::triangles(const std::vector<std::array<double, 3>>& points,
                                     const std::vector<uint32_t>& indices, const Rgb& colour) {
  // Corners at the same point (a cap's and a wall's) are one, to a tenth of a micrometre: a
  // reader needs no normals, and a rolled sheet's list is a third the size.
  std::map<std::array<int64_t, 3>, uint32_t> at;
  std::vector<uint32_t> corner(points.size());
  std::string coords, faces;
  for (size_t i = 0; i < points.size(); ++i) {
    const std::array<int64_t, 3> key{std::llround(points[i][0] * 1e4),
                                     std::llround(points[i][1] * 1e4),
                                     std::llround(points[i][2] * 1e4)};
    const auto [it, added] = at.try_emplace(key, static_cast<uint32_t>(at.size() + 1));
    corner[i] = it->second;  // IFC counts corners from 1
    if (!added) continue;
    coords += coords.empty() ? "(" : ",(";
    for (int k = 0; k < 3; ++k) {
      if (k) coords += ',';
      append_step_real(coords, static_cast<double>(key[static_cast<size_t>(k)]) / 1e4);
    }
    coords += ')';
  }
  for (size_t i = 0; i + 2 < indices.size(); i += 3) {
    const uint32_t a = corner[indices[i]], b = corner[indices[i + 1]], c = corner[indices[i + 2]];
    if (a == b || b == c || a == c) continue;  // a sliver closed up by the rounding
    faces += fmt::format("{}({},{},{})", faces.empty() ? "" : ",", a, b, c);
  }
  const int64_t list = w_.add(FMT_COMPILE("IFCCARTESIANPOINTLIST3D(({}))"), coords);
  // Not closed of itself: a screen's sheet is open where its tiles fill it, and they where it
  // holds them.
  const int64_t s =
      w_.add(FMT_COMPILE("IFCTRIANGULATEDFACESET({},$,.F.,({}),$)"), ref(list), faces);
  w_.add(FMT_COMPILE("IFCSTYLEDITEM({},({}),$)"), ref(s), ref(style(colour)));
  return s;
}

int64_t IfcGeometryWriter::representation_map(int64_t item) {
  const int64_t rep = w_.add(FMT_COMPILE("IFCSHAPEREPRESENTATION({},'Body','Tessellation',({}))"),
                             ref(body_), ref(item));
  return w_.add(FMT_COMPILE("IFCREPRESENTATIONMAP({},{})"), ref(world_), ref(rep));
}

int64_t IfcGeometryWriter::mapped(int64_t map, const std::array<double, 3>& origin,
                                  const std::array<double, 2>& x) {
  auto once = [&](const std::array<double, 3>& d) {
    auto it = directions_.find(d);
    return it != directions_.end() ? it->second : directions_[d] = direction(d[0], d[1], d[2]);
  };
  const int64_t op =
      w_.add(FMT_COMPILE("IFCCARTESIANTRANSFORMATIONOPERATOR3D({},{},{},1.,{})"),
             ref(once({x[0], x[1], 0})), ref(once({0, 0, 1})),
             ref(point(origin[0], origin[1], origin[2])), ref(once({x[1], -x[0], 0})));
  return w_.add(FMT_COMPILE("IFCMAPPEDITEM({},{})"), ref(map), ref(op));
}

int64_t IfcGeometryWriter::mapped_body(const std::vector<int64_t>& items) {
  const int64_t rep =
      w_.add(FMT_COMPILE("IFCSHAPEREPRESENTATION({},'Body','MappedRepresentation',{})"), ref(body_),
             step_refs(items));
  return w_.add(FMT_COMPILE("IFCPRODUCTDEFINITIONSHAPE($,$,({}))"), ref(rep));
}

int64_t IfcGeometryWriter::base_placement(double base) {
  if (base == 0) return world_;
  auto it = bases_.find(base);
  if (it != bases_.end()) return it->second;
  return bases_[base] = w_.add(FMT_COMPILE("IFCAXIS2PLACEMENT3D({},$,$)"), ref(point(0, 0, base)));
}

int64_t IfcGeometryWriter::style(const Rgb& c) {
  const uint32_t key = uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b;
  auto it = styles_.find(key);
  if (it != styles_.end()) return it->second;
  const int64_t colour = w_.add(FMT_COMPILE("IFCCOLOURRGB($,{},{},{})"), real(c.r / 255.0),
                                real(c.g / 255.0), real(c.b / 255.0));
  const int64_t shading = w_.add(FMT_COMPILE("IFCSURFACESTYLESHADING({},0.)"), ref(colour));
  return styles_[key] = w_.add(FMT_COMPILE("IFCSURFACESTYLE({},.BOTH.,({}))"),
                               step_string(hex_colour(c)), ref(shading));
}

}  // namespace curdle
