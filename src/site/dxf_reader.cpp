// dxflib calls back per entity; the entities are collected per block (model space is the
// block ""), and then the model's entities and the blocks they insert are placed.
#include "site/dxf_reader.h"

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "curdle/text.h"
#include "site/curves.h"
#include "site/dxf_checks.h"

namespace curdle::site {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kDeepestBlock = 16;
// How far from the plan's plane a vertex may stand before a shape is off it, drawing units.
constexpr double kPlaneTolerance = 1e-6;

struct Insert {
  std::string block, layer, handle;
  double x = 0, y = 0, sx = 1, sy = 1, angle = 0;  // angle in degrees
  int columns = 1, rows = 1;
  double column_spacing = 0, row_spacing = 0;
};

struct Block {
  double base_x = 0, base_y = 0;
  std::vector<Shape> shapes;
  std::vector<Insert> inserts;
};

// Layer names as the drawing wrote them: UTF-8, or Windows-1252 in older files; `\U+XXXX` is
// the DXF escape for any other character.
std::string decoded_name(const std::string& raw) {
  std::string text;
  if (valid_utf8(raw)) {
    text = raw;
  } else {
    static const char16_t kHigh[32] = {
        0x20AC, 0xFFFD, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
        0x2039, 0x0152, 0xFFFD, 0x017D, 0xFFFD, 0xFFFD, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
        0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0xFFFD, 0x017E, 0x0178};
    for (unsigned char c : raw) append_utf8(text, c < 0x80 ? c : (c < 0xA0 ? kHigh[c - 0x80] : c));
  }
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    unsigned cp = 0;
    if (text.compare(i, 3, "\\U+") == 0 && i + 7 <= text.size() &&
        std::sscanf(text.c_str() + i + 3, "%4x", &cp) == 1 && cp >= 0x20 &&
        (cp < 0xD800 || cp > 0xDFFF)) {
      append_utf8(out, cp);
      i += 6;
      continue;
    }
    out += text[i];
  }
  return out;
}

std::string hex_handle(int handle) { return handle >= 0 ? fmt::format("{:X}", handle) : ""; }

class Collector : public DL_CreationAdapter {
 public:
  Collector(const std::string& file, const DxfReading& reading) : file_(file), reading_(reading) {}

  std::map<std::string, Block> blocks;  // "" is model space
  std::map<std::string, int> layer_flags;
  std::set<std::string> layers_off;
  double unit_mm = 0;
  int insunits = 0;
  std::optional<std::string> error;  // the first fault; reading goes on but keeps nothing
  size_t passed_over = 0;            // texts, dimensions, hatches, points: not a site's shapes
  size_t flattened = 0;

  void setVariableInt(const std::string& key, int value, int) override {
    if (key == "$INSUNITS") insunits = value, unit_mm = insunits_mm(value);
  }
  void addLayer(const DL_LayerData& data) override {
    layer_flags[decoded_name(data.name)] = data.flags;
    if (data.off) layers_off.insert(decoded_name(data.name));
  }
  void addBlock(const DL_BlockData& data) override {
    finish_polyline();
    block_ = data.name;
    // Model and paper space blocks hold what the ENTITIES section holds (or a layout's).
    in_paper_ = data.name.rfind("*Paper_Space", 0) == 0 || data.name.rfind("*PAPER_SPACE", 0) == 0;
    if (data.name == "*Model_Space" || data.name == "*MODEL_SPACE") block_.clear();
    Block& b = blocks[block_];
    if (!block_.empty()) b.base_x = data.bpx, b.base_y = data.bpy;
  }
  void endBlock() override {
    finish_polyline();
    block_.clear();
    in_paper_ = false;
  }
  // dxflib calls endSection at every entity's end, POLYLINE's included, before its VERTEX
  // entities: a polyline ends at SEQEND, the next entity, the block's end or the file's.
  void endSequence() override { finish_polyline(); }

  void addLine(const DL_LineData& d) override {
    begin();
    if (std::fabs(d.z1 - d.z2) > kPlaneTolerance) return off_plane("LINE");
    Shape s = shape("LINE");
    s.path = {{d.x1, d.y1, 0}, {d.x2, d.y2, 0}};
    keep(std::move(s));
  }
  void addArc(const DL_ArcData& d) override {
    begin();
    if (!plan_entity("ARC") || !(d.radius > 0)) return;
    double sweep = std::fmod(d.angle2 - d.angle1, 360.0);
    if (sweep <= 0) sweep += 360;
    const double a0 = d.angle1 * kPi / 180, a1 = a0 + sweep * kPi / 180;
    Shape s = shape("ARC");
    s.path = {{d.cx + d.radius * std::cos(a0), d.cy + d.radius * std::sin(a0),
               tidy_bulge(bulge_of_sweep(sweep * kPi / 180))},
              {d.cx + d.radius * std::cos(a1), d.cy + d.radius * std::sin(a1), 0}};
    mirror_if_under(s);
    keep(std::move(s));
  }
  void addCircle(const DL_CircleData& d) override {
    begin();
    if (!plan_entity("CIRCLE") || !(d.radius > 0)) return;
    Shape s = shape("CIRCLE");
    s.path = {{d.cx - d.radius, d.cy, 1}, {d.cx + d.radius, d.cy, 1}};
    s.closed = true;
    mirror_if_under(s);
    keep(std::move(s));
  }
  void addEllipse(const DL_EllipseData& d) override {
    begin();
    if (std::fabs(d.mz) > kPlaneTolerance) return off_plane("ELLIPSE");
    const bool whole = std::fabs(std::fabs(d.angle2 - d.angle1) - 2 * kPi) < 1e-9 ||
                       (d.angle1 == 0 && d.angle2 == 0);
    Shape s = shape("ELLIPSE");
    const double to = whole ? d.angle1 + 2 * kPi : d.angle2;
    for (const Point& p :
         flatten_ellipse({d.cx, d.cy}, {d.mx, d.my}, d.ratio, d.angle1, to, tolerance()))
      s.path.push_back({p[0], p[1], 0});
    if (whole && s.path.size() > 1) s.path.pop_back(), s.closed = true;
    s.flattened = true;
    ++flattened;
    keep(std::move(s));
  }
  void addPolyline(const DL_PolylineData& d) override {
    begin();
    // 16 and 64: polygon and polyface meshes, which are surfaces rather than outlines.
    if (d.flags & (16 | 64)) {
      ++passed_over;
      return;
    }
    polyline_ = shape(d.flags & 8 ? "POLYLINE" : "LWPOLYLINE");
    polyline_->closed = d.flags & 1;
    polyline_z_.reset();
    polyline_mirrored_ = under();
  }
  void addVertex(const DL_VertexData& d) override {
    if (!polyline_) return;
    if (!polyline_z_) polyline_z_ = d.z;
    if (std::fabs(d.z - *polyline_z_) > kPlaneTolerance) {
      const Shape s = std::move(*polyline_);  // named by the POLYLINE, not its VERTEX
      polyline_.reset();
      return off_plane(s.entity, s.handle, s.layer);
    }
    if (++vertices_ > kMostVertices) return too_many();
    polyline_->path.push_back({d.x, d.y, std::isfinite(d.bulge) ? tidy_bulge(d.bulge) : 0});
  }
  void addSpline(const DL_SplineData& d) override {
    begin();
    spline_ = SplineParts{};
    spline_->degree = static_cast<int>(d.degree);
    spline_->closed = d.flags & 1;
    spline_->shape = shape("SPLINE");
  }
  void addControlPoint(const DL_ControlPointData& d) override {
    if (!spline_ || spline_->control.size() > kMostVertices) return;
    spline_->control.push_back({d.x, d.y});
    spline_->weights.push_back(d.w);
  }
  void addKnot(const DL_KnotData& d) override {
    if (spline_ && spline_->knots.size() <= kMostVertices) spline_->knots.push_back(d.k);
  }
  void addFitPoint(const DL_FitPointData& d) override {
    if (spline_ && spline_->fit.size() <= kMostVertices) spline_->fit.push_back({d.x, d.y});
  }
  void addInsert(const DL_InsertData& d) override {
    begin();
    if (in_paper_) return;
    Insert i{d.name, layer(), hex_handle(getAttributes().getHandle())};
    i.x = d.ipx, i.y = d.ipy, i.sx = d.sx, i.sy = d.sy, i.angle = d.angle;
    i.columns = std::max(1, d.cols), i.rows = std::max(1, d.rows);
    i.column_spacing = d.colSp, i.row_spacing = d.rowSp;
    if (under()) i.x = -i.x, i.sx = -i.sx, i.angle = 180 - i.angle;
    blocks[block_].inserts.push_back(std::move(i));
  }
  void addText(const DL_TextData&) override { pass_over(); }
  void addMText(const DL_MTextData&) override { pass_over(); }
  void addPoint(const DL_PointData&) override { pass_over(); }
  void addHatch(const DL_HatchData&) override { pass_over(); }
  void addSolid(const DL_SolidData&) override { pass_over(); }
  void addLeader(const DL_LeaderData&) override { pass_over(); }
  void addDimLinear(const DL_DimensionData&, const DL_DimLinearData&) override { pass_over(); }
  void addDimAlign(const DL_DimensionData&, const DL_DimAlignedData&) override { pass_over(); }

  // After the last group: what is still open is finished.
  void finish() {
    finish_polyline();
    finish_spline();
  }

 private:
  struct SplineParts {
    int degree = 3;
    bool closed = false;
    std::vector<Point> control, fit;
    std::vector<double> knots, weights;
    Shape shape;
  };

  // Any new entity ends the polyline or spline before it (LWPOLYLINE has no end marker).
  void begin() {
    finish_polyline();
    finish_spline();
  }
  void pass_over() {
    begin();
    ++passed_over;
  }
  std::string layer() { return decoded_name(getAttributes().getLayer()); }
  Shape shape(const char* entity) {
    Shape s;
    s.layer = layer();
    s.handle = hex_handle(getAttributes().getHandle());
    s.entity = entity;
    return s;
  }
  double tolerance() const {
    const double mm = reading_.unit_mm > 0 ? reading_.unit_mm : (unit_mm > 0 ? unit_mm : 1);
    return reading_.chord_tolerance_mm / mm;
  }
  // Entities drawn in their own coordinate system: the plan's (extrusion 0, 0, 1) or the plan
  // seen from below (0, 0, -1: a mirrored copy), never one standing off it.
  bool under() {
    const double* n = getExtrusion()->getDirection();
    return std::fabs(n[0]) < 1e-9 && std::fabs(n[1]) < 1e-9 && n[2] < 0;
  }
  bool plan_entity(const char* entity) {
    const double* n = getExtrusion()->getDirection();
    if (std::fabs(n[0]) < 1e-9 && std::fabs(n[1]) < 1e-9 && n[2] != 0) return true;
    off_plane(entity);
    return false;
  }
  void mirror_if_under(Shape& s) {
    if (!under()) return;
    for (ContourVertex& v : s.path) v.x = -v.x, v.bulge = v.bulge == 0 ? 0 : -v.bulge;
  }
  void off_plane(const std::string& entity) {
    off_plane(entity, hex_handle(getAttributes().getHandle()), layer());
  }
  void off_plane(const std::string& entity, const std::string& handle, const std::string& layer) {
    fail(
        fmt::format("{}: the {} {}on layer \"{}\" does not lie in the plan's plane (its points "
                    "stand at different heights, or it is drawn in a tilted coordinate "
                    "system); flatten the drawing (e.g. FLATTEN in AutoCAD) and save it again",
                    file_, entity, handle.empty() ? "" : "with handle " + handle + " ", layer));
  }
  void too_many() {
    fail(
        fmt::format("{}: holds more than {} shapes or {} vertices, more than a site drawing "
                    "needs; keep only the layers of the surface (e.g. WBLOCK or LAYISO, then "
                    "save as DXF)",
                    file_, kMostShapes, kMostVertices));
  }
  void fail(std::string message) {
    if (!error) error = std::move(message);
  }
  void keep(Shape s) {
    if (error || in_paper_) return;
    if (++shapes_ > kMostShapes) return too_many();
    if ((vertices_ += s.path.size()) > kMostVertices) return too_many();
    blocks[block_].shapes.push_back(std::move(s));
  }
  void finish_polyline() {
    if (!polyline_) return;
    Shape s = std::move(*polyline_);
    polyline_.reset();
    if (polyline_mirrored_)
      for (ContourVertex& v : s.path) v.x = -v.x, v.bulge = v.bulge == 0 ? 0 : -v.bulge;
    // A closed polyline that repeats its first vertex at the end is closed once.
    if (s.closed && s.path.size() > 2 && s.path.back().x == s.path.front().x &&
        s.path.back().y == s.path.front().y)
      s.path.pop_back();
    if (s.path.size() >= 2) keep(std::move(s));
  }
  void finish_spline() {
    if (!spline_) return;
    SplineParts sp = std::move(*spline_);
    spline_.reset();
    std::vector<Point> points;
    if (!sp.control.empty()) {
      bool weighted = false;
      for (double w : sp.weights) weighted = weighted || w != 1;
      points = flatten_spline(sp.degree, sp.knots, sp.control,
                              weighted ? sp.weights : std::vector<double>{}, tolerance());
    }
    if (points.empty() && sp.fit.size() >= 2) points = sp.fit;  // no usable knots: its fit points
    if (points.empty()) {
      ++passed_over;
      return;
    }
    Shape s = std::move(sp.shape);
    for (const Point& p : points) s.path.push_back({p[0], p[1], 0});
    s.closed = sp.closed || (points.size() > 2 && points.front() == points.back());
    if (s.closed && s.path.size() > 2 && points.front() == points.back()) s.path.pop_back();
    s.flattened = true;
    ++flattened;
    keep(std::move(s));
  }

  std::string file_;
  DxfReading reading_;
  std::string block_;
  bool in_paper_ = false;
  std::optional<Shape> polyline_;
  std::optional<double> polyline_z_;
  bool polyline_mirrored_ = false;
  std::optional<SplineParts> spline_;
  size_t shapes_ = 0, vertices_ = 0;
};

// A block reference's placement: base point to origin, scale, rotation, then the insertion
// point; arrays repeat it along the rotated columns and rows.
struct Placement {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;  // x' = a x + c y + e, y' = b x + d y + f
  Point apply(double x, double y) const { return {a * x + c * y + e, b * x + d * y + f}; }
  Placement then(const Placement& o) const {  // this, then o
    return {o.a * a + o.c * b, o.b * a + o.d * b,       o.a * c + o.c * d,
            o.b * c + o.d * d, o.a * e + o.c * f + o.e, o.b * e + o.d * f + o.f};
  }
  double determinant() const { return a * d - b * c; }
  // A similarity (rotation, uniform scale, mirror) keeps circular arcs circular.
  bool keeps_arcs() const {
    return std::fabs(a * a + b * b - (c * c + d * d)) < 1e-9 * (a * a + b * b) &&
           std::fabs(a * c + b * d) < 1e-9 * (a * a + b * b);
  }
};

Placement placement_of(const Insert& i, const Block& b, int column, int row) {
  const double t = i.angle * kPi / 180, cs = std::cos(t), sn = std::sin(t);
  const double ox = column * i.column_spacing, oy = row * i.row_spacing;
  Placement p;
  p.a = cs * i.sx, p.b = sn * i.sx, p.c = -sn * i.sy, p.d = cs * i.sy;
  const Point base = {p.a * b.base_x + p.c * b.base_y, p.b * b.base_x + p.d * b.base_y};
  p.e = i.x - base[0] + cs * ox - sn * oy;
  p.f = i.y - base[1] + sn * ox + cs * oy;
  return p;
}

Shape placed(const Shape& s, const Placement& p, double tolerance) {
  Shape out = s;
  out.path.clear();
  const bool mirror = p.determinant() < 0;
  if (p.keeps_arcs() || !has_arcs(s.path)) {
    for (const ContourVertex& v : s.path) {
      const Point q = p.apply(v.x, v.y);
      out.path.push_back({q[0], q[1], mirror ? -v.bulge : v.bulge});
    }
    return out;
  }
  // Stretched unevenly, an arc is an ellipse's: placed as chords.
  Contour path = s.path;
  if (!s.closed) path.back().bulge = 0;
  for (const auto& q : flatten(path, tolerance)) {
    const Point r = p.apply(q[0], q[1]);
    out.path.push_back({r[0], r[1], 0});
  }
  out.flattened = true;
  return out;
}

class Placer {
 public:
  Placer(const Collector& c, const std::string& file, double tolerance, Drawing& drawing)
      : c_(c), file_(file), tolerance_(tolerance), drawing_(drawing) {}

  void place(const std::string& name, const Placement& p, const std::string& insert_layer,
             int insert, int depth) {
    const auto it = c_.blocks.find(name);
    if (it == c_.blocks.end()) {
      missing_.insert(name);
      return;
    }
    if (depth > kDeepestBlock)
      throw SiteError(
          fmt::format("{}: block \"{}\" is nested more than {} deep (or inserts "
                      "itself); explode it and save the drawing again",
                      file_, name, kDeepestBlock));
    for (const Shape& s : it->second.shapes) {
      if (drawing_.shapes.size() >= kMostShapes) throw SiteError(too_many());
      Shape out = placed(s, p, tolerance_);
      // Counted as placed: a block's few vertices, inserted in arrays, can be millions.
      if ((vertices_ += out.path.size()) > kMostVertices) throw SiteError(too_many());
      if (depth > 0 && (out.layer == "0" || out.layer.empty())) out.layer = insert_layer;
      out.insert = insert;
      drawing_.shapes.push_back(std::move(out));
    }
    for (const Insert& i : it->second.inserts) {
      const std::string layer = depth > 0 && i.layer == "0" ? insert_layer : i.layer;
      const int top = depth == 0 ? next_insert_++ : insert;
      if (static_cast<uint64_t>(i.columns) * static_cast<uint64_t>(i.rows) > kMostShapes)
        throw SiteError(too_many());
      const auto inner = c_.blocks.find(i.block);
      if (inner == c_.blocks.end()) {
        missing_.insert(i.block);
        continue;
      }
      for (int col = 0; col < i.columns; ++col)
        for (int row = 0; row < i.rows; ++row)
          place(i.block, placement_of(i, inner->second, col, row).then(p), layer, top, depth + 1);
    }
  }
  std::string too_many() const {
    return fmt::format(
        "{}: places more than {} shapes or {} vertices once its blocks are inserted, more "
        "than a site drawing needs; keep only the layers of the surface",
        file_, kMostShapes, kMostVertices);
  }
  const std::set<std::string>& missing() const { return missing_; }

 private:
  const Collector& c_;
  std::string file_;
  double tolerance_;
  Drawing& drawing_;
  int next_insert_ = 0;
  size_t vertices_ = 0;
  std::set<std::string> missing_;
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
  Collector collector(file_name, reading);
  {
    std::istringstream in{std::string(bytes)};
    DL_Dxf dxf;
    dxf.in(in, &collector);
  }
  collector.finish();
  if (collector.error) throw SiteError(*collector.error);

  Drawing drawing;
  drawing.format = "DXF";
  drawing.unit_mm = collector.unit_mm;
  static const std::map<int, std::string> kUnitNames = {{1, "in"}, {2, "ft"}, {4, "mm"},
                                                        {5, "cm"}, {6, "m"},  {14, "dm"}};
  if (const auto it = kUnitNames.find(collector.insunits); it != kUnitNames.end())
    drawing.unit_name = it->second;
  else if (collector.insunits != 0)
    drawing.unit_name = fmt::format("$INSUNITS {}", collector.insunits);
  const double mm =
      reading.unit_mm > 0 ? reading.unit_mm : (drawing.unit_mm > 0 ? drawing.unit_mm : 1);
  Placer placer(collector, file_name, reading.chord_tolerance_mm / mm, drawing);
  placer.place("", Placement{}, "0", -1, 0);
  for (const auto& [name, flags] : collector.layer_flags)
    if ((flags & 1) || collector.layers_off.count(name)) drawing.hidden.push_back(name);
  if (collector.flattened)
    drawing.notes.push_back(
        fmt::format("{} ellipses and splines flattened to chords within "
                    "{:g} mm",
                    collector.flattened, reading.chord_tolerance_mm));
  if (!placer.missing().empty()) {
    std::string names;
    for (const auto& n : placer.missing()) names += (names.empty() ? "" : ", ") + n;
    drawing.notes.push_back("blocks inserted but not defined, passed over: " + names);
  }
  return drawing;
}

}  // namespace curdle::site
