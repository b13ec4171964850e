// The groups (dxf_groups.h) are read a record at a time: a record is a group 0 and what follows
// it. The model's entities and each block's are collected as shapes in their block's frame,
// then the model is placed with the blocks it inserts. Entities drawn in an object coordinate
// system (ARC, CIRCLE, LWPOLYLINE, 2-D POLYLINE, INSERT, HATCH) are turned into the plan by
// AutoCAD's arbitrary axis algorithm (DXF Reference, "Object Coordinate Systems").
#include "site/dxf_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "curdle/stop.h"
#include "site/curves.h"
#include "site/dxf_blocks.h"
#include "site/dxf_checks.h"
#include "site/dxf_groups.h"
#include "site/dxf_hatch.h"
#include "site/dxf_spline.h"
#include "site/wide_polyline.h"

namespace curdle::site {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Record {
  std::string_view type;
  size_t line = 0;
  std::vector<DxfGroup> groups;
};

class Reader {
 public:
  Reader(std::string_view bytes, const std::string& file, const DxfReading& reading)
      : groups_(bytes, file), file_(file), reading_(reading) {}

  std::map<std::string, Block> blocks;  // "" is model space
  std::map<std::string, int> layer_flags;
  std::set<std::string> layers_off;
  int insunits = 0;
  int precision = 4;
  size_t passed_over = 0;  // texts, dimensions, points: not a site's shapes
  size_t flattened = 0, fitted = 0, wide = 0, wide_closed = 0, hatches = 0, off_plane_ = 0;
  std::vector<std::string> notes;

  void read() {
    Record r;
    std::string section;
    while (record(r)) {
      stop_point();  // the server's budget, a client gone, Python's Ctrl-C
      if (r.type == "SECTION") {
        section = value_of(r, 2).value_or("");
        if (section == "HEADER") header(r);
        continue;
      }
      if (r.type == "ENDSEC") {
        // Variables written after the header's ENDSEC (old dxflib writers, LibreCAD's library)
        // are the header's still, as ezdxf and CAD read them.
        if (section == "HEADER") header(r);
        finish_polyline();
        section.clear();
        continue;
      }
      if (r.type == "EOF") break;
      if (section == "TABLES") {
        if (r.type == "LAYER") layer_entry(r);
      } else if (section == "BLOCKS" || section == "ENTITIES") {
        if (r.type == "BLOCK") {
          finish_polyline();
          begin_block(r);
        } else if (r.type == "ENDBLK") {
          finish_polyline();
          block_.clear();
          in_paper_ = false;
        } else if (section == "ENTITIES" && !block_.empty()) {
          block_.clear();  // an ENDBLK missing: the entities are the model's
          entity(r);
        } else {
          entity(r);
        }
      }
    }
    finish_polyline();
  }

  double tolerance() const {
    const double mm =
        reading_.unit_mm > 0 ? reading_.unit_mm : std::max(insunits_mm(insunits), 0.0);
    return reading_.chord_tolerance_mm / (mm > 0 ? mm : 1);
  }

 private:
  bool record(Record& r) {
    DxfGroup g;
    r.groups.clear();
    // Groups before the first 0 (a damaged start) are passed over.
    do {
      if (!groups_.next(g)) return false;
    } while (g.code != 0);
    r.type = g.value;
    r.line = g.line;
    while (groups_.next(g)) {
      if (g.code == 0) {
        groups_.put_back(g);
        break;
      }
      if (r.groups.size() >= 4 * kMostVertices + 64)
        throw InputError(
            fmt::format("{}: the {} at line {} holds more groups than a site "
                        "drawing's entity needs",
                        file_, r.type, r.line));
      r.groups.push_back(g);
    }
    return true;
  }

  static std::optional<std::string_view> value_of(const Record& r, int code) {
    for (const DxfGroup& g : r.groups)
      if (g.code == code) return g.value;
    return std::nullopt;
  }
  double real(const Record& r, int code, double fallback, std::string_view what) const {
    return groups_.real_of(r.groups, code, fallback, what);
  }
  int64_t integer(const Record& r, int code, int64_t fallback, std::string_view what) const {
    return groups_.integer_of(r.groups, code, fallback, what);
  }

  void header(const Record& r) {
    for (size_t i = 0; i + 1 < r.groups.size(); ++i) {
      if (r.groups[i].code != 9) continue;
      const DxfGroup& v = r.groups[i + 1];
      if (r.groups[i].value == "$INSUNITS" && v.code == 70) {
        const int64_t code = groups_.integer(v, "header's $INSUNITS");
        if (code < 0 || code > 24)
          throw InputError(
              fmt::format("{}: line {}: $INSUNITS is {}, which is no unit code (0 to 24 in the DXF "
                          "Reference); save the drawing again with its units set (UNITS)",
                          file_, v.line, code));
        insunits = static_cast<int>(code);
      }
      if (r.groups[i].value == "$LUPREC" && v.code == 70) {
        const int64_t p = groups_.integer(v, "header's $LUPREC");
        if (p >= 0 && p <= 8) precision = static_cast<int>(p);
      }
    }
  }

  void layer_entry(const Record& r) {
    const auto name = value_of(r, 2);
    if (!name) return;
    const std::string n = decoded_name(*name);
    layer_flags[n] = static_cast<int>(integer(r, 70, 0, "LAYER " + n));
    if (integer(r, 62, 7, "LAYER " + n) < 0) layers_off.insert(n);
  }

  void begin_block(const Record& r) {
    const std::string name = decoded_name(value_of(r, 2).value_or(""));
    block_ = name;
    in_paper_ = name.rfind("*Paper_Space", 0) == 0 || name.rfind("*PAPER_SPACE", 0) == 0;
    if (name == "*Model_Space" || name == "*MODEL_SPACE") block_.clear();
    Block& b = blocks[block_];
    if (!block_.empty())
      b.base_x = real(r, 10, 0, "BLOCK " + name), b.base_y = real(r, 20, 0, "BLOCK " + name);
  }

  // ---- Entities -------------------------------------------------------------------------

  struct Common {
    std::string handle, layer, name;  // name: "LWPOLYLINE 2A", for messages
    double nx = 0, ny = 0, nz = 1;    // the extrusion, normalised
  };

  Common common(const Record& r) {
    Common c;
    c.handle = std::string(value_of(r, 5).value_or(""));
    for (char& ch : c.handle)
      if (static_cast<unsigned char>(ch) < 0x20) ch = '?';
    c.layer = decoded_name(value_of(r, 8).value_or("0"));
    c.name = c.handle.empty() ? fmt::format("{} at line {}", r.type, r.line)
                              : fmt::format("{} {}", r.type, c.handle);
    c.nx = real(r, 210, 0, c.name), c.ny = real(r, 220, 0, c.name), c.nz = real(r, 230, 1, c.name);
    const double l = std::sqrt(c.nx * c.nx + c.ny * c.ny + c.nz * c.nz);
    if (l > 0) c.nx /= l, c.ny /= l, c.nz /= l;
    return c;
  }
  // Drawn in the plan, or in it seen from below (extrusion 0, 0, -1: x mirrored).
  static bool in_plan(const Common& c) {
    return std::fabs(c.nx) < 1e-9 && std::fabs(c.ny) < 1e-9 && c.nz != 0;
  }
  // A shape off the plan's plane is a fault of its layer: refused where the recipe names the
  // layer, passed over elsewhere (a 3-D detail on a layer of its own).
  void off_plane(const Common& c) {
    Shape s = shape(c, c.name.substr(0, c.name.find(' ')));
    s.fault = fmt::format(
        "the {} on layer \"{}\"{} does not lie in the plan's plane (its points stand at "
        "different heights, or it is drawn in a tilted coordinate system); flatten the drawing "
        "(e.g. FLATTEN in AutoCAD) and save it again",
        with_handle(c), c.layer, in_block());
    s.path = {{0, 0, 0}, {0, 0, 0}};
    ++off_plane_;
    keep(std::move(s));
  }
  static std::string with_handle(const Common& c) {
    return c.handle.empty()
               ? c.name
               : fmt::format("{} with handle {}", c.name.substr(0, c.name.find(' ')), c.handle);
  }
  std::string in_block() const {
    return block_.empty() ? "" : fmt::format(" in block \"{}\"", block_);
  }

  Shape shape(const Common& c, std::string_view entity) const {
    Shape s;
    s.layer = c.layer;
    s.handle = c.handle;
    s.entity = std::string(entity);
    s.block = block_;
    return s;
  }
  void keep(Shape s) {
    if (in_paper_) return;
    if (++shapes_ > kMostShapes || (vertices_ += s.path.size()) > kMostVertices)
      throw InputError(fmt::format(
          "{}: holds more than {} shapes or {} vertices, more than a site drawing needs; keep "
          "only the layers of the surface (e.g. WBLOCK or LAYISO, then save as DXF)",
          file_, kMostShapes, kMostVertices));
    blocks[block_].shapes.push_back(std::move(s));
  }
  static void mirror(Shape& s) {
    for (ContourVertex& v : s.path) v.x = -v.x, v.bulge = v.bulge == 0 ? 0 : -v.bulge;
    for (ContourVertex& v : s.strip) v.x = -v.x, v.bulge = v.bulge == 0 ? 0 : -v.bulge;
  }

  void entity(const Record& r) {
    if (r.type != "VERTEX" && r.type != "SEQEND") finish_polyline();
    // Paper space (group 67 = 1) holds the sheets, not the site.
    if (in_paper_ || integer(r, 67, 0, r.type) == 1) return;
    if (r.type == "LINE") return line(r);
    if (r.type == "ARC" || r.type == "CIRCLE") return arc(r);
    if (r.type == "ELLIPSE") return ellipse(r);
    if (r.type == "LWPOLYLINE") return lwpolyline(r);
    if (r.type == "POLYLINE") return polyline(r);
    if (r.type == "VERTEX") return vertex(r);
    if (r.type == "SEQEND" || r.type == "ATTRIB") return;
    if (r.type == "SPLINE") return spline(r);
    if (r.type == "INSERT") return insert(r);
    if (r.type == "HATCH") return hatch(r);
    ++passed_over;
  }

  void line(const Record& r) {
    const Common c = common(r);
    const double z1 = real(r, 30, 0, c.name), z2 = real(r, 31, 0, c.name);
    if (std::fabs(z1 - z2) > kPlaneTolerance) return off_plane(c);
    Shape s = shape(c, "LINE");
    s.path = {{real(r, 10, 0, c.name), real(r, 20, 0, c.name), 0},
              {real(r, 11, 0, c.name), real(r, 21, 0, c.name), 0}};
    keep(std::move(s));
  }

  void arc(const Record& r) {
    const Common c = common(r);
    if (!in_plan(c)) return off_plane(c);
    const double cx = real(r, 10, 0, c.name), cy = real(r, 20, 0, c.name);
    const double radius = real(r, 40, 0, c.name);
    if (!(radius > 0)) {
      ++passed_over;
      return;
    }
    Shape s = shape(c, r.type);
    if (r.type == "CIRCLE") {
      s.path = {{cx - radius, cy, 1}, {cx + radius, cy, 1}};
      s.closed = true;
    } else {
      const double from = real(r, 50, 0, c.name), to = real(r, 51, 0, c.name);
      double sweep = std::fmod(to - from, 360.0);
      if (sweep <= 0) sweep += 360;
      const double a0 = from * kPi / 180, a1 = a0 + sweep * kPi / 180;
      const double bulge = tidy_bulge(bulge_of_sweep(sweep * kPi / 180));
      // A whole turn is two half turns: one edge cannot sweep 360°.
      if (sweep >= 360 - 1e-9) {
        s.path = {{cx + radius * std::cos(a0), cy + radius * std::sin(a0), 1},
                  {cx - radius * std::cos(a0), cy - radius * std::sin(a0), 1}};
        s.closed = true;
      } else {
        s.path = {{cx + radius * std::cos(a0), cy + radius * std::sin(a0), bulge},
                  {cx + radius * std::cos(a1), cy + radius * std::sin(a1), 0}};
      }
    }
    if (c.nz < 0) mirror(s);
    keep(std::move(s));
  }

  void ellipse(const Record& r) {
    const Common c = common(r);
    if (!in_plan(c)) return off_plane(c);
    const double cx = real(r, 10, 0, c.name), cy = real(r, 20, 0, c.name);
    const double mx = real(r, 11, 0, c.name), my = real(r, 21, 0, c.name);
    if (std::fabs(real(r, 31, 0, c.name)) > kPlaneTolerance) return off_plane(c);
    const double ratio = real(r, 40, 1, c.name);
    double from = real(r, 41, 0, c.name), to = real(r, 42, 2 * kPi, c.name);
    Shape s = shape(c, "ELLIPSE");
    if (!(ratio > 0) || !(std::hypot(mx, my) > 0)) {
      s.fault = fmt::format(
          "the {} has an axis ratio of {:g} and a major axis {:g} long: it "
          "encloses nothing",
          c.name, ratio, std::hypot(mx, my));
      s.path = {{cx, cy, 0}, {cx, cy, 0}};
      keep(std::move(s));
      return;
    }
    const bool whole = std::fabs(std::fabs(to - from) - 2 * kPi) < 1e-9 || (from == 0 && to == 0);
    if (whole) to = from + 2 * kPi;
    while (to <= from) to += 2 * kPi;
    // The minor axis is the normal's cross the major, as long as the ratio says.
    const double sign = c.nz < 0 ? -1 : 1;
    const Point minor{-sign * my * ratio, sign * mx * ratio};
    for (const Point& p : flatten_curve(
             [&](double t) {
               return Point{cx + mx * std::cos(t) + minor[0] * std::sin(t),
                            cy + my * std::cos(t) + minor[1] * std::sin(t)};
             },
             from, to, tolerance()))
      s.path.push_back({p[0], p[1], 0});
    if (whole && s.path.size() > 1) s.path.pop_back(), s.closed = true;
    s.flattened = true;
    ++flattened;
    keep(std::move(s));
  }

  // An LWPOLYLINE's vertices: each 10 begins one; 20, 40, 41 and 42 belong to the last.
  void lwpolyline(const Record& r) {
    const Common c = common(r);
    if (!in_plan(c)) return off_plane(c);
    const int64_t flags = integer(r, 70, 0, c.name);
    const double constant = real(r, 43, 0, c.name);
    std::vector<WideVertex> v;
    for (const DxfGroup& g : r.groups) {
      if (g.code == 10) {
        if (v.size() >= kMostVertices) break;
        v.push_back({groups_.real(g, c.name), 0, 0, constant, constant});
      } else if (!v.empty() && g.code == 20) {
        v.back().y = groups_.real(g, c.name);
      } else if (!v.empty() && g.code == 40) {
        v.back().start_width = groups_.real(g, c.name);
      } else if (!v.empty() && g.code == 41) {
        v.back().end_width = groups_.real(g, c.name);
      } else if (!v.empty() && g.code == 42) {
        v.back().bulge = tidy_bulge(groups_.real(g, c.name));
      }
    }
    polyline_ = Polyline{shape(c, "LWPOLYLINE"), std::move(v), (flags & 1) != 0, c.nz < 0};
    finish_polyline();
  }

  void polyline(const Record& r) {
    const Common c = common(r);
    const int64_t flags = integer(r, 70, 0, c.name);
    // 16 and 64: polygon and polyface meshes, which are surfaces rather than outlines.
    if (flags & (16 | 64)) {
      ++passed_over;
      return;
    }
    const bool three_d = flags & 8;
    if (!three_d && !in_plan(c)) return off_plane(c);
    polyline_ = Polyline{shape(c, "POLYLINE"), {}, (flags & 1) != 0, !three_d && c.nz < 0};
    polyline_->three_d = three_d;
    polyline_->common = c;
    polyline_->start_width = real(r, 40, 0, c.name);
    polyline_->end_width = real(r, 41, 0, c.name);
  }

  void vertex(const Record& r) {
    if (!polyline_) return;
    const std::string& what = polyline_->common.name;
    // 16: a spline frame's control point, not on the curve CAD draws.
    if (integer(r, 70, 0, what) & 16) return;
    const double z = real(r, 30, 0, what);
    if (polyline_->three_d) {
      if (!polyline_->z) polyline_->z = z;
      if (std::fabs(z - *polyline_->z) > kPlaneTolerance) {
        const Common c = polyline_->common;
        polyline_.reset();
        return off_plane(c);
      }
    }
    if (polyline_->vertices.size() >= kMostVertices) return;
    polyline_->vertices.push_back(
        {real(r, 10, 0, what), real(r, 20, 0, what), tidy_bulge(real(r, 42, 0, what)),
         real(r, 40, polyline_->start_width, what), real(r, 41, polyline_->end_width, what)});
  }

  void finish_polyline() {
    if (!polyline_) return;
    Polyline p = std::move(*polyline_);
    polyline_.reset();
    Shape& s = p.shape;
    bool has_width = false;
    for (const WideVertex& v : p.vertices) {
      s.path.push_back({v.x, v.y, v.bulge});
      has_width = has_width || v.start_width > 0 || v.end_width > 0;
    }
    s.closed = p.closed;
    // A closed polyline that repeats its first vertex at the end is closed once.
    if (s.closed && s.path.size() > 2 && s.path.back().x == s.path.front().x &&
        s.path.back().y == s.path.front().y)
      s.path.pop_back();
    if (s.path.size() < 2) return;
    if (has_width && !s.closed) {
      s.strip = swept_outline(p.vertices, tolerance());
      ++wide;
    } else if (has_width) {
      ++wide_closed;
    }
    if (p.mirrored) mirror(s);
    keep(std::move(s));
  }

  void spline(const Record& r) {
    const Common c = common(r);
    if (std::fabs(c.nx) > 1e-9 || std::fabs(c.ny) > 1e-9) return off_plane(c);
    const SplineReading curve = read_spline(r.groups, groups_, c.name, tolerance());
    if (!curve.flat) return off_plane(c);
    Shape s = shape(c, "SPLINE");
    if (!curve.why.empty()) {
      s.fault = fmt::format("the {} on layer \"{}\"{} {}", c.name, c.layer, in_block(), curve.why);
      s.path = {{curve.first[0], curve.first[1], 0}, {curve.last[0], curve.last[1], 0}};
      keep(std::move(s));
      return;
    }
    const std::vector<Point>& points = curve.points;
    for (const Point& p : points) s.path.push_back({p[0], p[1], 0});
    s.closed = curve.closed || (points.size() > 2 && points.front() == points.back());
    if (s.closed && s.path.size() > 2 && points.front() == points.back()) s.path.pop_back();
    s.flattened = true;
    ++flattened;
    fitted += curve.fitted;
    keep(std::move(s));
  }

  void insert(const Record& r) {
    const Common c = common(r);
    if (!in_plan(c)) return off_plane(c);
    Insert i;
    i.block = decoded_name(value_of(r, 2).value_or(""));
    i.layer = c.layer;
    i.handle = c.handle;
    i.x = real(r, 10, 0, c.name), i.y = real(r, 20, 0, c.name);
    i.sx = real(r, 41, 1, c.name), i.sy = real(r, 42, 1, c.name);
    i.angle = real(r, 50, 0, c.name);
    i.columns = std::max<int64_t>(1, integer(r, 70, 1, c.name));
    i.rows = std::max<int64_t>(1, integer(r, 71, 1, c.name));
    i.column_spacing = real(r, 44, 0, c.name), i.row_spacing = real(r, 45, 0, c.name);
    i.ocs_x = c.nz < 0 ? -1 : 1;
    if (!(std::fabs(i.sx) > 0 && std::fabs(i.sy) > 0)) {
      notes.push_back(
          fmt::format("the {} of block \"{}\" on layer \"{}\" is scaled by 0, so it "
                      "places nothing: passed over",
                      c.name, i.block, c.layer));
      return;
    }
    blocks[block_].inserts.push_back(std::move(i));
  }

  // HATCH: its boundary paths are closed shapes on its layer.
  void hatch(const Record& r) {
    const Common c = common(r);
    if (!in_plan(c)) return off_plane(c);
    std::optional<HatchBoundaries> b =
        hatch_boundaries(r.groups, groups_, c.name, c.layer, tolerance());
    if (!b) return;
    ++hatches;
    flattened += b->flattened;
    for (Contour& loop : b->loops) {
      Shape s = shape(c, "HATCH");
      s.closed = true;
      s.path = std::move(loop);
      if (c.nz < 0) mirror(s);
      keep(std::move(s));
    }
  }

  struct Polyline {
    Shape shape;
    std::vector<WideVertex> vertices;
    bool closed = false, mirrored = false, three_d = false;
    Common common;
    double start_width = 0, end_width = 0;
    std::optional<double> z;
  };

  DxfGroups groups_;
  std::string file_;
  DxfReading reading_;
  std::string block_;
  bool in_paper_ = false;
  std::optional<Polyline> polyline_;
  size_t shapes_ = 0, vertices_ = 0;
};

}  // namespace

double insunits_mm(int code) {
  switch (code) {
    case 1:
      return 25.4;  // inches
    case 2:
      return 304.8;  // feet
    case 4:
      return 1;  // millimetres
    case 5:
      return 10;  // centimetres
    case 6:
      return 1000;  // metres
    case 14:
      return 100;  // decimetres
    default:
      return 0;
  }
}

Drawing read_dxf(std::string_view bytes, const std::string& file_name, const DxfReading& reading) {
  check_dxf_bytes(bytes, file_name);
  Reader reader(bytes, file_name, reading);
  reader.read();

  Drawing drawing;
  drawing.format = "DXF";
  drawing.unit_mm = insunits_mm(reader.insunits);
  drawing.precision = reader.precision;
  static const std::map<int, std::string> kUnitNames = {{1, "in"}, {2, "ft"}, {4, "mm"},
                                                        {5, "cm"}, {6, "m"},  {14, "dm"}};
  if (const auto it = kUnitNames.find(reader.insunits); it != kUnitNames.end())
    drawing.unit_name = it->second;
  else if (reader.insunits != 0)
    drawing.unit_name = fmt::format("$INSUNITS {}", reader.insunits);
  const std::set<std::string> missing =
      place_blocks(reader.blocks, file_name, reader.tolerance(), drawing);
  for (const auto& [name, flags] : reader.layer_flags)
    if ((flags & 1) || reader.layers_off.count(name)) drawing.hidden.push_back(name);
  if (reader.flattened)
    drawing.notes.push_back(fmt::format(
        "{} ellipses, splines and curved hatch edges flattened to chords within {:g} mm{}",
        reader.flattened, reading.chord_tolerance_mm,
        reader.fitted ? fmt::format(" ({} splines given by fit points, drawn through them as "
                                    "CAD draws them)",
                                    reader.fitted)
                      : ""));
  if (reader.wide)
    drawing.notes.push_back(fmt::format(
        "{} open polylines drawn with width read as the strips they cover where they are not "
        "part of an outline",
        reader.wide));
  if (reader.wide_closed)
    drawing.notes.push_back(fmt::format(
        "{} closed polylines drawn with width read by their centre lines", reader.wide_closed));
  if (reader.hatches)
    drawing.notes.push_back(fmt::format("{} hatches read by their boundary paths", reader.hatches));
  drawing.notes.insert(drawing.notes.end(), reader.notes.begin(), reader.notes.end());
  if (!missing.empty()) {
    std::string names;
    for (const auto& n : missing) names += (names.empty() ? "" : ", ") + n;
    drawing.notes.push_back("blocks inserted but not defined, passed over: " + names);
  }
  return drawing;
}

}  // namespace curdle::site
