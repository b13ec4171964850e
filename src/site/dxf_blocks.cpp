#include "site/dxf_blocks.h"

#include <fmt/format.h>

#include <cmath>

#include "curdle/stop.h"
#include "site/curves.h"

namespace curdle::site {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kDeepestBlock = 16;

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

Placement placement_of(const Insert& i, const Block& b, int64_t column, int64_t row) {
  const double t = i.angle * kPi / 180, cs = std::cos(t), sn = std::sin(t);
  const double ox = static_cast<double>(column) * i.column_spacing,
               oy = static_cast<double>(row) * i.row_spacing;
  Placement p;
  p.a = cs * i.sx, p.b = sn * i.sx, p.c = -sn * i.sy, p.d = cs * i.sy;
  const Point base = {p.a * b.base_x + p.c * b.base_y, p.b * b.base_x + p.d * b.base_y};
  p.e = i.x - base[0] + cs * ox - sn * oy;
  p.f = i.y - base[1] + sn * ox + cs * oy;
  // Drawn from below: the whole placement is mirrored into the plan.
  return p.then(Placement{i.ocs_x, 0, 0, 1, 0, 0});
}

Contour placed_path(const Contour& path, bool closed, const Placement& p, double tolerance,
                    bool& flattened) {
  Contour out;
  const bool mirror = p.determinant() < 0;
  if (p.keeps_arcs() || !has_arcs(path)) {
    for (const ContourVertex& v : path) {
      const Point q = p.apply(v.x, v.y);
      out.push_back({q[0], q[1], mirror ? -v.bulge : v.bulge});
    }
    return out;
  }
  // Stretched unevenly, an arc is an ellipse's: placed as chords.
  Contour flat = path;
  if (!closed) flat.back().bulge = 0;
  for (const auto& q : flatten(flat, tolerance)) {
    const Point r = p.apply(q[0], q[1]);
    out.push_back({r[0], r[1], 0});
  }
  flattened = true;
  return out;
}

Shape placed(const Shape& s, const Placement& p, double tolerance) {
  Shape out = s;
  bool flattened = false;
  out.path = placed_path(s.path, s.closed, p, tolerance, flattened);
  if (!s.strip.empty()) out.strip = placed_path(s.strip, true, p, tolerance, flattened);
  out.flattened = s.flattened || flattened;
  return out;
}

class Placer {
 public:
  Placer(const std::map<std::string, Block>& blocks, const std::string& file, double tolerance,
         Drawing& drawing)
      : blocks_(blocks), file_(file), tolerance_(tolerance), drawing_(drawing) {}

  void place(const std::string& name, const Placement& p, const std::string& insert_layer,
             int insert, const std::string& insert_handle, int depth) {
    const auto it = blocks_.find(name);
    if (it == blocks_.end()) {
      missing_.insert(name);
      return;
    }
    if (depth > kDeepestBlock)
      throw InputError(
          fmt::format("{}: block \"{}\" is nested more than {} deep (or inserts "
                      "itself); explode it and save the drawing again",
                      file_, name, kDeepestBlock));
    if (++placements_ > kMostPlacements) throw InputError(too_many());
    stop_point();
    for (const Shape& s : it->second.shapes) {
      if (drawing_.shapes.size() >= kMostShapes) throw InputError(too_many());
      Shape out = depth == 0 ? s : placed(s, p, tolerance_);
      // Counted as placed: a block's few vertices, inserted in arrays, can be millions.
      if ((vertices_ += out.path.size() + out.strip.size()) > kMostVertices)
        throw InputError(too_many());
      if (depth > 0 && (out.layer == "0" || out.layer.empty())) out.layer = insert_layer;
      out.insert = insert;
      out.insert_handle = insert_handle;
      drawing_.shapes.push_back(std::move(out));
    }
    for (const Insert& i : it->second.inserts) {
      const std::string layer = depth > 0 && i.layer == "0" ? insert_layer : i.layer;
      const int top = depth == 0 ? next_insert_++ : insert;
      const std::string& top_handle = depth == 0 ? i.handle : insert_handle;
      if (static_cast<uint64_t>(i.columns) * static_cast<uint64_t>(i.rows) > kMostPlacements)
        throw InputError(too_many());
      const auto inner = blocks_.find(i.block);
      if (inner == blocks_.end()) {
        missing_.insert(i.block);
        continue;
      }
      for (int64_t col = 0; col < i.columns; ++col)
        for (int64_t row = 0; row < i.rows; ++row)
          place(i.block, placement_of(i, inner->second, col, row).then(p), layer, top, top_handle,
                depth + 1);
    }
  }
  std::string too_many() const {
    return fmt::format(
        "{}: places more than {} shapes or {} vertices (or {} block placements) once its "
        "blocks are inserted, more than a site drawing needs; keep only the layers of the "
        "surface",
        file_, kMostShapes, kMostVertices, kMostPlacements);
  }
  const std::set<std::string>& missing() const { return missing_; }

 private:
  const std::map<std::string, Block>& blocks_;
  std::string file_;
  double tolerance_;
  Drawing& drawing_;
  int next_insert_ = 0;
  size_t vertices_ = 0, placements_ = 0;
  std::set<std::string> missing_;
};

}  // namespace

std::set<std::string> place_blocks(const std::map<std::string, Block>& blocks,
                                   const std::string& file, double tolerance, Drawing& drawing) {
  Placer placer(blocks, file, tolerance, drawing);
  placer.place("", Placement{}, "0", -1, "", 0);
  return placer.missing();
}

}  // namespace curdle::site
