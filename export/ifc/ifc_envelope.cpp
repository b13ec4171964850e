#include "export/ifc/ifc_envelope.h"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <array>
#include <cmath>

#include "layout/framed_boxes.h"
#include "layout/framed_corner.h"

namespace curdle {
namespace {

using Vec = std::array<double, 3>;

using step::real;
using step::ref;
using step::text;

// A direction with rounding dust (6E-17 for 0) cleared.
Vec tidy(Vec v) {
  for (double& c : v)
    if (std::fabs(c) < 1e-12) c = 0;
  return v;
}

// A frame in the building: origin, x along the façade, y up, z out of the wall.
struct Axes {
  Vec origin, x, y{0, 0, 1}, z;
  // A point or direction of the building in these axes' coordinates.
  Vec local(const Vec& p, bool point) const {
    Vec d = p;
    if (point)
      for (int k = 0; k < 3; ++k) d[k] -= origin[k];
    return tidy({d[0] * x[0] + d[1] * x[1] + d[2] * x[2], d[0] * y[0] + d[1] * y[1] + d[2] * y[2],
                 d[0] * z[0] + d[1] * z[1] + d[2] * z[2]});
  }
};

// The axes of a face's piece: at its outer face's start, along its chord.
Axes face_axes(const FramedBox& b) {
  Axes a;
  const Vec along{b.along[0], b.along[1], 0};
  a.x = along;
  a.z = {b.along[1], -b.along[0], 0};  // the outside is on the right of the strip
  const double half = b.length / 2, in = b.depth / 2;
  a.origin = {b.centre[0] - along[0] * half + a.z[0] * in,
              b.centre[1] - along[1] * half + a.z[1] * in, b.centre[2] - b.height / 2};
  return a;
}

}  // namespace

IfcEnvelopeWriter::IfcEnvelopeWriter(StepWriter& w, IfcGeometryWriter& g, const Layout& layout,
                                     std::function<StepRoot(std::string_view)> root)
    : w_(w), g_(g), l_(layout), root_(std::move(root)) {}

size_t IfcEnvelopeWriter::facade_of(const Element& e) const {
  return static_cast<size_t>(framed_facade(l_, e) - l_.frames().data());
}

IfcEnvelopeWriter::Placed IfcEnvelopeWriter::unit(const Element& e, int64_t container,
                                                  const Rgb& colour) {
  const std::array<double, 2> depth = framed_depth(l_, e);  // a header runs in by its length
  const double t = depth[1] - depth[0];
  std::vector<FramedBox> boxes;
  for (const Rect& r : e.shape) {
    const std::vector<FramedBox> more = framed_boxes(l_, r, depth[0], depth[1]);
    boxes.insert(boxes.end(), more.begin(), more.end());
  }
  const Axes own = face_axes(boxes.front());
  const int64_t frame = g_.axes(own.origin, tidy(own.z), tidy(own.x));
  Placed p;
  p.placement = w_.add(FMT_COMPILE("IFCLOCALPLACEMENT({},{})"), ref(container), ref(frame));
  std::vector<int64_t> solids;
  if (const auto corner = framed_corner(l_, e, t)) {  // one prism, cut to the corner's angle
    const Vec up = own.local({0, 0, 1}, false), east = own.local({1, 0, 0}, false);
    const int64_t at = position(own.local({own.origin[0], own.origin[1], corner->base}, true),
                                tidy(up), tidy(east));
    solids.push_back(
        g_.solid_placed(corner_profile(*corner, own.origin), at, corner->height, colour));
    boxes.clear();
  }
  for (const FramedBox& b : boxes) {
    // Each face's solid from its outer face inwards: its own axes, `t` behind the face.
    const Axes face = face_axes(b);
    const Vec back{face.origin[0] - face.z[0] * t, face.origin[1] - face.z[1] * t, face.origin[2]};
    const int64_t at =
        position(own.local(back, true), own.local(face.z, false), own.local(face.x, false));
    solids.push_back(g_.solid_placed(face_profile(b.length, b.height), at, t, colour));
  }
  p.shape = g_.body(solids);
  return p;
}

IfcEnvelopeWriter::Placed IfcEnvelopeWriter::backing(const SurfaceFrame& f, int64_t container) {
  const double top = f.height > 0 ? f.height : l_.height;
  const std::vector<FramedBox> boxes =
      framed_backing(l_, Rect{f.start, 0, f.length, top}, l_.backing()->from, l_.thickness, 1e300);
  Placed p;
  if (boxes.empty()) return p;
  const Axes own = face_axes(boxes.front());
  const int64_t frame = g_.axes(own.origin, tidy(own.z), tidy(own.x));
  p.placement = w_.add(FMT_COMPILE("IFCLOCALPLACEMENT({},{})"), ref(container), ref(frame));
  std::vector<int64_t> solids;
  for (const FramedBox& b : boxes) {
    const Axes face = face_axes(b);
    const Vec back{face.origin[0] - face.z[0] * b.depth, face.origin[1] - face.z[1] * b.depth,
                   face.origin[2]};
    const int64_t at =
        position(own.local(back, true), own.local(face.z, false), own.local(face.x, false));
    solids.push_back(
        g_.solid_placed(face_profile(b.length, b.height), at, b.depth, kBackingColour));
  }
  p.shape = g_.body(solids);
  return p;
}

int64_t IfcEnvelopeWriter::face_profile(double length, double height) {
  auto it = profiles_.find({length, height});
  if (it != profiles_.end()) return it->second;
  g_.set_local_origin(0, 0);
  return profiles_[{length, height}] = g_.rectangle(Rect{0, 0, length, height});
}

int64_t IfcEnvelopeWriter::corner_profile(const FramedPrism& p, const Vec& origin) {
  Ring ring;
  std::vector<int64_t> key;
  for (const auto& v : p.footprint) {
    ring.push_back({v[0] - origin[0], v[1] - origin[1]});
    key.push_back(std::llround(ring.back()[0] * 1e3));
    key.push_back(std::llround(ring.back()[1] * 1e3));
  }
  auto it = corner_profiles_.find(key);
  if (it != corner_profiles_.end()) return it->second;
  g_.set_local_origin(0, 0);
  return corner_profiles_[key] = g_.profile_with_holes(ring, {});
}

int64_t IfcEnvelopeWriter::position(const Vec& origin, const Vec& axis, const Vec& ref) {
  // Rounded to a micrometre, so that the same position in two units is written once.
  std::array<double, 9> key{};
  for (int k = 0; k < 3; ++k)
    key[k] = std::round(origin[k] * 1e3) / 1e3, key[3 + k] = std::round(axis[k] * 1e9) / 1e9,
    key[6 + k] = std::round(ref[k] * 1e9) / 1e9;
  auto it = positions_.find(key);
  if (it != positions_.end()) return it->second;
  return positions_[key] =
             g_.axes({key[0], key[1], key[2]}, {key[3], key[4], key[5]}, {key[6], key[7], key[8]});
}

int64_t IfcEnvelopeWriter::placement_on(const SurfaceFrame& f, double u, double v,
                                        int64_t container, double to) {
  const BuildingPoint o = frame_point(f, u, v, 0);
  std::array<double, 2> d = frame_direction(f, u);
  if (to > u) {  // along the chord to `to`: an opening in a curved wall is straight
    const BuildingPoint e = frame_point(f, to, v, 0);
    const double n = std::hypot(e[0] - o[0], e[1] - o[1]);
    d = {(e[0] - o[0]) / n, (e[1] - o[1]) / n};
  }
  const int64_t frame = g_.axes({o[0], o[1], o[2]}, tidy({d[1], -d[0], 0}), tidy({d[0], d[1], 0}));
  return w_.add(FMT_COMPILE("IFCLOCALPLACEMENT({},{})"), ref(container), ref(frame));
}

std::vector<std::pair<int64_t, double>> IfcEnvelopeWriter::walls(
    int64_t container, const std::vector<std::vector<int64_t>>& parts) {
  std::vector<std::pair<int64_t, double>> contained;
  const double t = l_.thickness;
  std::vector<int64_t> wall_ids;
  for (size_t k = 0; k < l_.frames().size(); ++k) {
    const SurfaceFrame& f = l_.frames()[k];
    const std::string name = "Wall " + f.name;
    // A one-brick wall's body is its backing leaf; a leaf's shape is its units' (nested in it).
    const Placed body = l_.backing() ? backing(f, container) : Placed{};
    const int64_t wall = w_.add(
        FMT_COMPILE("IFCWALL({},{},{},$,{},{},{},.SOLIDWALL.)"), root_("wall " + f.name),
        text(name), text(fmt::format("{:g} mm along the envelope from {:g} mm", f.length, f.start)),
        ref(body.placement ? body.placement : placement_on(f, f.start, 0, container)),
        body.shape ? fmt::format("#{}", body.shape) : std::string("$"), text(f.name));
    wall_ids.push_back(wall);
    // Its common set, as BIM tools sort walls by it: the façade's name, and outside.
    const int64_t reference = w_.add(
        FMT_COMPILE("IFCPROPERTYSINGLEVALUE('Reference',$,IFCIDENTIFIER({}),$)"), text(f.name));
    const int64_t external = w_.add("IFCPROPERTYSINGLEVALUE('IsExternal',$,IFCBOOLEAN(.T.),$)");
    const int64_t common = w_.add(FMT_COMPILE("IFCPROPERTYSET({},'Pset_WallCommon',$,({},{}))"),
                                  root_("wall-common " + f.name), ref(reference), ref(external));
    w_.add(FMT_COMPILE("IFCRELDEFINESBYPROPERTIES({},$,$,({}),{})"),
           root_("wall-common-rel " + f.name), ref(wall), ref(common));
    // Its units nested in it, and so in the storeys through it (a part is not contained as
    // well): IfcRelAggregates would say the same, but web-ifc then subtracts the wall's openings
    // from every unit (already cut to them), taking 6 s to open the pavilion instead of 3.
    if (!parts[k].empty())
      w_.add(FMT_COMPILE("IFCRELNESTS({},$,$,{},{})"), root_("wall-parts " + f.name), ref(wall),
             step_refs(parts[k]));
  }
  for (const int64_t wall : wall_ids) contained.push_back({wall, 0.0});
  for (size_t i = 0; i < l_.openings_given; ++i) {
    const Rect& o = l_.openings[i];
    const SurfaceFrame* f = frame_at(l_.frames(), o.x + o.w / 2);
    const size_t k = static_cast<size_t>(f - l_.frames().data());
    const EnvelopeFrames& envelope = *l_.envelope;
    const bool door = i < envelope.opening_kinds.size() && envelope.opening_kinds[i] == "door";
    const std::string id = i < envelope.opening_names.size() ? envelope.opening_names[i]
                                                             : fmt::format("opening-{}", i + 1);
    // The opening through the wall, 10 mm proud of both faces so that no reader leaves a skin
    // (and on a curve by its chord's sagitta more, at the back).
    g_.set_local_origin(0, 0);
    const BuildingPoint a = frame_point(*f, o.x, 0, 0), b = frame_point(*f, o.right(), 0, 0);
    const double chord = std::hypot(b[0] - a[0], b[1] - a[1]);
    const double radius = f->bulge == 0 ? 0 : f->length / std::fabs(4 * std::atan(f->bulge));
    const double sag = f->bulge == 0 ? 0 : radius - std::sqrt(radius * radius - chord * chord / 4);
    const int64_t cut = g_.solid_placed(g_.rectangle(Rect{0, 0, chord, o.h}),
                                        g_.axes({0, 0, -t - 10 - sag}, {0, 0, 1}, {1, 0, 0}),
                                        t + 20 + sag, Rgb{255, 255, 255});
    const int64_t opening = w_.add(
        FMT_COMPILE("IFCOPENINGELEMENT({},{},$,'opening',{},{},{},.OPENING.)"),
        root_("opening " + id), text(id), ref(placement_on(*f, o.x, o.y, container, o.right())),
        ref(g_.body({cut})), text(id));
    w_.add(FMT_COMPILE("IFCRELVOIDSELEMENT({},$,$,{},{})"), root_("void " + id), ref(wall_ids[k]),
           ref(opening));
    // The window's glass or the door's leaf, 40 mm thick in the middle of the reveal.
    const int64_t panel = g_.solid_placed(g_.rectangle(Rect{0, 0, chord, o.h}),
                                          g_.axes({0, 0, -t / 2 - 20}, {0, 0, 1}, {1, 0, 0}), 40,
                                          door ? Rgb{110, 80, 60} : Rgb{160, 200, 220});
    const std::string entity =
        door ? fmt::format("IFCDOOR({},{},$,'door',{},{},{},{},{},.DOOR.,.SINGLE_SWING_LEFT.,$)",
                           root_("door " + id), text(id),
                           ref(placement_on(*f, o.x, o.y, container, o.right())),
                           ref(g_.body({panel})), text(id), real(o.h), real(o.w))
             : fmt::format("IFCWINDOW({},{},$,'window',{},{},{},{},{},.WINDOW.,.SINGLE_PANEL.,$)",
                           root_("window " + id), text(id),
                           ref(placement_on(*f, o.x, o.y, container, o.right())),
                           ref(g_.body({panel})), text(id), real(o.h), real(o.w));
    const int64_t filler = w_.add(entity);
    w_.add(FMT_COMPILE("IFCRELFILLSELEMENT({},$,$,{},{})"), root_("fill " + id), ref(opening),
           ref(filler));
    contained.push_back({filler, o.y});
  }
  return contained;
}

}  // namespace curdle
