// libxml2 gives the tree; this walks it (groups, layers, transforms, <use>), and SVG++ parses
// each transform and each shape's path data into events that become contours. Circular arcs
// stay arcs where the transform keeps circles circular; the arc's centre comes from SVG's
// endpoint form (SVG 1.1, appendix F.6.5).
#include "site/svg_reader.h"

#include <fmt/format.h>
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <svgpp/svgpp.hpp>

#include "curdle/stop.h"
#include "curdle/text.h"
#include "site/curves.h"

namespace curdle::site {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kDeepest = 64;
constexpr int kDeepestUse = 16;
// Elements placed through <use>, counting each place a shared one is used and everything walked
// below it: 15 levels of ten uses of an empty group are 10^15 visits that place nothing.
// (250,000 take a quarter of a second; the fuzzer's sanitized build found a million too slow.)
constexpr size_t kMostVisits = 250000;
const char* const kSvg = "http://www.w3.org/2000/svg";
const char* const kInkscape = "http://www.inkscape.org/namespaces/inkscape";
const char* const kXlink = "http://www.w3.org/1999/xlink";

// x' = a x + c y + e, y' = b x + d y + f, as SVG writes a matrix.
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  Point apply(double x, double y) const { return {a * x + c * y + e, b * x + d * y + f}; }
  // This after `inner`: applied to a point, inner first.
  Affine after(const Affine& inner) const {
    return {a * inner.a + c * inner.b,     b * inner.a + d * inner.b,
            a * inner.c + c * inner.d,     b * inner.c + d * inner.d,
            a * inner.e + c * inner.f + e, b * inner.e + d * inner.f + f};
  }
  double determinant() const { return a * d - b * c; }
  bool similar() const {  // circles stay circles
    const double s = a * a + b * b;
    return std::fabs(s - (c * c + d * d)) < 1e-9 * s && std::fabs(a * c + b * d) < 1e-9 * s;
  }
};

// An attribute's value as written; names taken from it are shown_name'd where they become a
// layer's or a shape's.
std::string attribute(const xmlNode* node, const char* name, const char* ns = nullptr) {
  xmlChar* v = ns ? xmlGetNsProp(node, reinterpret_cast<const xmlChar*>(name),
                                 reinterpret_cast<const xmlChar*>(ns))
                  : xmlGetNoNsProp(node, reinterpret_cast<const xmlChar*>(name));
  if (!v) return {};
  std::string s(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return s;
}

bool is_svg(const xmlNode* node, const char* name) {
  return node->type == XML_ELEMENT_NODE && node->ns &&
         xmlStrEqual(node->ns->href, reinterpret_cast<const xmlChar*>(kSvg)) &&
         xmlStrEqual(node->name, reinterpret_cast<const xmlChar*>(name));
}

std::string name_of(const xmlNode* node) {
  const std::string id = shown_name(attribute(node, "id"));
  return fmt::format("<{}> {}", reinterpret_cast<const char*>(node->name),
                     id.empty() ? fmt::format("at line {}", xmlGetLineNo(node)) : "\"" + id + "\"");
}

// The path events of SVG++ (absolute coordinates, no shorthands) as contours in the drawing's
// frame: `to` maps user units there.
class PathCollector {
 public:
  PathCollector(const Affine& to, double tolerance) : to_(to), tolerance_(tolerance) {}

  void path_move_to(double x, double y, svgpp::tag::coordinate::absolute) {
    end_subpath(false);
    start_ = current_ = {x, y};
    add(x, y);
  }
  void path_line_to(double x, double y, svgpp::tag::coordinate::absolute) {
    begin();
    current_ = {x, y};
    add(x, y);
  }
  void path_cubic_bezier_to(double x1, double y1, double x2, double y2, double x, double y,
                            svgpp::tag::coordinate::absolute) {
    begin();
    const Point p0 = current_;
    curve([&](double t) {
      const double u = 1 - t;
      return Point{u * u * u * p0[0] + 3 * u * u * t * x1 + 3 * u * t * t * x2 + t * t * t * x,
                   u * u * u * p0[1] + 3 * u * u * t * y1 + 3 * u * t * t * y2 + t * t * t * y};
    });
    current_ = {x, y};
  }
  void path_quadratic_bezier_to(double x1, double y1, double x, double y,
                                svgpp::tag::coordinate::absolute) {
    begin();
    const Point p0 = current_;
    curve([&](double t) {
      const double u = 1 - t;
      return Point{u * u * p0[0] + 2 * u * t * x1 + t * t * x,
                   u * u * p0[1] + 2 * u * t * y1 + t * t * y};
    });
    current_ = {x, y};
  }
  void path_elliptical_arc_to(double rx, double ry, double rotation, bool large, bool sweep,
                              double x, double y, svgpp::tag::coordinate::absolute);
  void path_close_subpath() {
    end_subpath(true);
    current_ = start_;
  }
  void path_exit() { end_subpath(false); }

  std::vector<std::pair<Contour, bool>> paths;  // each with whether it is closed

 private:
  void add(double x, double y) {
    const Point p = to_.apply(x, y);
    path_.push_back({p[0], p[1], 0});
  }
  // A drawing command after a close (with no move) starts a subpath at the current point.
  void begin() {
    if (path_.empty()) add(current_[0], current_[1]);
  }
  void curve(const std::function<Point(double)>& f) {
    const double scale = std::sqrt(std::fabs(to_.determinant()));
    const std::vector<Point> points = flatten_curve(f, 0, 1, tolerance_ / (scale > 0 ? scale : 1));
    for (size_t i = 1; i < points.size(); ++i) add(points[i][0], points[i][1]);
  }
  void end_subpath(bool closed) {
    if (closed && path_.size() > 1 && path_.back().x == path_.front().x &&
        path_.back().y == path_.front().y && path_.back().bulge == 0)
      path_.pop_back();
    if (path_.size() >= 2) paths.emplace_back(std::move(path_), closed);
    path_.clear();
  }

  Affine to_;
  double tolerance_;
  Point start_{0, 0}, current_{0, 0};
  Contour path_;
};

void PathCollector::path_elliptical_arc_to(double rx, double ry, double rotation, bool large,
                                           bool sweep, double x, double y,
                                           svgpp::tag::coordinate::absolute) {
  begin();
  const Point p1 = current_;
  current_ = {x, y};
  rx = std::fabs(rx), ry = std::fabs(ry);
  if ((p1[0] == x && p1[1] == y)) return;
  if (rx == 0 || ry == 0 || !std::isfinite(rx) || !std::isfinite(ry)) return add(x, y);
  // SVG 1.1, F.6.5: the centre and angles from the end points, radii scaled up if too small.
  const double phi = rotation * kPi / 180, cs = std::cos(phi), sn = std::sin(phi);
  const double hx = (p1[0] - x) / 2, hy = (p1[1] - y) / 2;
  const double x1 = cs * hx + sn * hy, y1 = -sn * hx + cs * hy;
  const double lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
  if (lambda > 1) rx *= std::sqrt(lambda), ry *= std::sqrt(lambda);
  const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
  const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
  const double coef = (large != sweep ? 1 : -1) * std::sqrt(std::max(0.0, num / den));
  const double cx1 = coef * rx * y1 / ry, cy1 = -coef * ry * x1 / rx;
  const double cx = cs * cx1 - sn * cy1 + (p1[0] + x) / 2,
               cy = sn * cx1 + cs * cy1 + (p1[1] + y) / 2;
  const double start = std::atan2((y1 - cy1) / ry, (x1 - cx1) / rx);
  double delta = std::atan2((-y1 - cy1) / ry, (-x1 - cx1) / rx) - start;
  if (sweep && delta < 0) delta += 2 * kPi;
  if (!sweep && delta > 0) delta -= 2 * kPi;
  auto at = [&](double t) {
    const double a = start + t * delta;
    return Point{cx + rx * cs * std::cos(a) - ry * sn * std::sin(a),
                 cy + rx * sn * std::cos(a) + ry * cs * std::sin(a)};
  };
  if (std::fabs(rx - ry) <= 1e-9 * rx && to_.similar()) {
    // A circular arc: kept as bulges (two, past a half turn), turned with a mirror.
    const int halves = std::fabs(delta) > kPi ? 2 : 1;
    const double bulge =
        tidy_bulge(std::tan(delta / halves / 4)) * (to_.determinant() < 0 ? -1 : 1);
    for (int h = 1; h <= halves; ++h) {
      path_.back().bulge = bulge;
      const Point p = h == halves ? Point{x, y} : at(0.5);
      add(p[0], p[1]);
    }
    return;
  }
  curve(at);
}

// An element's viewBox (x, y, width, height), if it has one; InputError for one that is not four
// numbers with a width and height above 0.
std::optional<std::array<double, 4>> view_box(const xmlNode* node, const std::string& file) {
  const std::string view = attribute(node, "viewBox");
  if (view.empty()) return std::nullopt;
  std::array<double, 4> box{};
  std::string spaced = view;
  for (char& ch : spaced)
    if (ch == ',') ch = ' ';
  if (std::sscanf(spaced.c_str(), "%lf %lf %lf %lf", &box[0], &box[1], &box[2], &box[3]) != 4 ||
      !(box[2] > 0 && box[3] > 0) || !std::isfinite(box[0] + box[1] + box[2] + box[3]))
    throw InputError(
        fmt::format("{}: {} has the viewBox \"{}\", not four numbers with a width "
                    "and height above 0",
                    file, name_of(node), view.substr(0, 100)));
  return box;
}

// A shape's length attribute: a number of user units (px allowed).
double length(const xmlNode* node, const char* name, const std::string& file, double fallback) {
  const std::string text = attribute(node, name);
  if (text.empty()) return fallback;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  std::string rest(end ? end : "");
  while (!rest.empty() && std::isspace(static_cast<unsigned char>(rest.back()))) rest.pop_back();
  if (end == text.c_str() || !std::isfinite(v) || !(rest.empty() || rest == "px"))
    throw InputError(
        fmt::format("{}: {} has {}=\"{}\"; curdle reads shapes' lengths in user units "
                    "(a number), not percentages or other units",
                    file, name_of(node), name, text));
  return v;
}

// The shape as path data: what SVG++ parses for <path>, and the others written as paths.
std::string path_data(const xmlNode* node, const std::string& file) {
  const std::string tag = reinterpret_cast<const char*>(node->name);
  auto n = [&](const char* a, double fallback = 0) { return length(node, a, file, fallback); };
  if (tag == "path") return attribute(node, "d");
  if (tag == "rect") {
    const double x = n("x"), y = n("y"), w = n("width"), h = n("height");
    if (!(w > 0 && h > 0)) return {};
    return fmt::format("M{:.17g},{:.17g}h{:.17g}v{:.17g}h{:.17g}z", x, y, w, h, -w);
  }
  if (tag == "circle" || tag == "ellipse") {
    const double cx = n("cx"), cy = n("cy");
    const double rx = tag == "circle" ? n("r") : n("rx"), ry = tag == "circle" ? rx : n("ry");
    if (!(rx > 0 && ry > 0)) return {};
    return fmt::format(
        "M{0:.17g},{1:.17g}A{2:.17g},{3:.17g} 0 0 1 {4:.17g},{1:.17g}"
        "A{2:.17g},{3:.17g} 0 0 1 {0:.17g},{1:.17g}z",
        cx - rx, cy, rx, ry, cx + rx);
  }
  if (tag == "line")
    return fmt::format("M{:.17g},{:.17g}L{:.17g},{:.17g}", n("x1"), n("y1"), n("x2"), n("y2"));
  if (tag == "polyline" || tag == "polygon") {
    const std::string points = attribute(node, "points");
    if (points.empty()) return {};
    return "M" + points + (tag == "polygon" ? "z" : "");
  }
  return {};
}

class Walker {
 public:
  Walker(const std::string& file, double tolerance, Drawing& drawing)
      : file_(file), tolerance_(tolerance), drawing_(drawing) {}

  void index(const xmlNode* node, int depth) {
    if (depth > kDeepest)
      throw InputError(fmt::format("{}: nests elements more than {} deep", file_, kDeepest));
    for (const xmlNode* c = node->children; c; c = c->next) {
      if (c->type != XML_ELEMENT_NODE) continue;
      stop_point();
      if (++elements_ > 4 * kMostShapes)
        throw InputError(
            fmt::format("{}: holds more than {} elements, more than a site drawing "
                        "needs; keep only the layers of the surface",
                        file_, 4 * kMostShapes));
      const std::string id = attribute(c, "id");
      if (!id.empty()) ids_.emplace(id, c);
      index(c, depth + 1);
    }
  }

  // Whether the drawing has Inkscape's layers: then they are its layers, else its top-level
  // groups are (Illustrator's layers, a CAD program's).
  void find_layers(const xmlNode* root) {
    for (const xmlNode* c = root->children; c; c = c->next)
      if (is_svg(c, "g") || is_svg(c, "svg") || is_svg(c, "a") || is_svg(c, "switch")) {
        if (attribute(c, "groupmode", kInkscape) == "layer") inkscape_layers_ = true;
        find_layers(c);
      }
  }

  // `layer`: the layer the shapes below belong to; `names`: the named groups inside it, by
  // which a recipe may also pick a part of a layer.
  void walk(const xmlNode* node, const Affine& ctm, const std::string& layer,
            const std::vector<std::string>& names, int depth, int uses) {
    if (depth > kDeepest)
      throw InputError(fmt::format("{}: nests groups more than {} deep", file_, kDeepest));
    for (const xmlNode* c = node->children; c; c = c->next) {
      if (c->type != XML_ELEMENT_NODE || !c->ns ||
          !xmlStrEqual(c->ns->href, reinterpret_cast<const xmlChar*>(kSvg)))
        continue;
      const std::string tag = reinterpret_cast<const char*>(c->name);
      stop_point();
      if (uses > 0) count_visit();  // the elements a <use> places, however many it shares
      if (attribute(c, "display") == "none") continue;
      if (tag == "defs" || tag == "symbol" || tag == "clipPath" || tag == "mask" ||
          tag == "pattern" || tag == "marker")
        continue;  // drawn only where used
      Affine here = ctm.after(transform_of(c));
      if (tag == "svg") here = here.after(viewport(c, std::nullopt, std::nullopt));
      if (tag == "g" || tag == "a" || tag == "switch" || tag == "svg") {
        std::string label = shown_name(attribute(c, "label", kInkscape));
        const std::string id = shown_name(attribute(c, "id"));
        const bool is_layer =
            inkscape_layers_ ? attribute(c, "groupmode", kInkscape) == "layer" : depth == 0;
        std::vector<std::string> inner = names;
        if (is_layer) {
          std::string name = label;
          if (name.empty()) name = shown_name(attribute(c, "data-name"));
          if (name.empty()) name = id;
          walk(c, here, name.empty() ? layer : name, {}, depth + 1, uses);
          continue;
        }
        if (!label.empty()) inner.push_back(label);
        if (!id.empty()) inner.push_back(id);
        walk(c, here, layer, inner, depth + 1, uses);
      } else if (tag == "use") {
        use(c, here, layer, names, depth, uses);
      } else {
        shape(c, here, layer, names);
      }
    }
  }

 private:
  Affine transform_of(const xmlNode* node) {
    const std::string text = attribute(node, "transform");
    if (text.empty()) return {};
    struct Matrix {
      Affine m;
      void transform_matrix(const boost::array<double, 6>& v) {
        m = m.after(Affine{v[0], v[1], v[2], v[3], v[4], v[5]});
      }
    } matrix;
    try {
      svgpp::value_parser<svgpp::tag::type::transform_list>::parse(
          svgpp::tag::attribute::transform(), matrix, text, svgpp::tag::source::attribute());
    } catch (const std::exception&) {
      throw InputError(fmt::format("{}: {} has a transform curdle cannot read: \"{}\"", file_,
                                   name_of(node), text.substr(0, 200)));
    }
    const Affine& m = matrix.m;
    if (!std::isfinite(m.a + m.b + m.c + m.d + m.e + m.f) || m.determinant() == 0)
      throw InputError(
          fmt::format("{}: {} has a transform that is not finite or flattens it to "
                      "a line: \"{}\"",
                      file_, name_of(node), text.substr(0, 200)));
    return m;
  }

  // A nested <svg>'s or a used <symbol>'s viewport: x, y, then its viewBox fitted into its width
  // and height (preserveAspectRatio's default, xMidYMid meet, or none). A <use> gives the
  // symbol's width and height.
  Affine viewport(const xmlNode* node, std::optional<double> width, std::optional<double> height) {
    const bool symbol = is_svg(node, "symbol");
    const double x = symbol ? 0 : length(node, "x", file_, 0);
    const double y = symbol ? 0 : length(node, "y", file_, 0);
    Affine at{1, 0, 0, 1, x, y};
    const std::optional<std::array<double, 4>> view = view_box(node, file_);
    if (!view) return at;
    const std::array<double, 4>& box = *view;
    auto size = [&](const char* key, std::optional<double> given, double fallback) {
      if (given) return *given;
      const std::string text = attribute(node, key);
      if (text.empty() || text.back() == '%') return fallback;  // 100 %: the viewBox's own size
      return length(node, key, file_, fallback);
    };
    const double w = size("width", width, box[2]), h = size("height", height, box[3]);
    double sx = w / box[2], sy = h / box[3];
    double dx = 0, dy = 0;
    if (attribute(node, "preserveAspectRatio").rfind("none", 0) != 0) {
      const double s = std::min(sx, sy);
      dx = (w - box[2] * s) / 2, dy = (h - box[3] * s) / 2;
      sx = sy = s;
    }
    return at.after(Affine{sx, 0, 0, sy, dx - box[0] * sx, dy - box[1] * sy});
  }

  void use(const xmlNode* node, const Affine& ctm, const std::string& layer,
           const std::vector<std::string>& names, int depth, int uses) {
    std::string href = attribute(node, "href", kXlink);
    if (href.empty()) href = attribute(node, "href");
    const auto it = href.size() > 1 && href[0] == '#' ? ids_.find(href.substr(1)) : ids_.end();
    if (it == ids_.end()) {
      ++unresolved_;
      return;
    }
    if (uses >= kDeepestUse)
      throw InputError(fmt::format("{}: {} refers to <use> more than {} deep (or to itself)", file_,
                                   name_of(node), kDeepestUse));
    const Affine placed =
        ctm.after(Affine{1, 0, 0, 1, length(node, "x", file_, 0), length(node, "y", file_, 0)});
    const xmlNode* target = it->second;
    const std::string tag = reinterpret_cast<const char*>(target->name);
    count_visit();
    if (tag == "symbol" || tag == "svg") {
      const std::string w = attribute(node, "width"), h = attribute(node, "height");
      const auto given = [&](const std::string& text, const char* key) -> std::optional<double> {
        if (text.empty() || text.back() == '%') return std::nullopt;
        return length(node, key, file_, 0);
      };
      walk(target,
           placed.after(transform_of(target))
               .after(viewport(target, given(w, "width"), given(h, "height"))),
           layer, names, depth + 1, uses + 1);
    } else if (tag == "g") {
      walk(target, placed.after(transform_of(target)), layer, names, depth + 1, uses + 1);
    } else {
      shape(target, placed.after(transform_of(target)), layer, names);
    }
  }

  void count_visit() {
    if (++visits_ > kMostVisits)
      throw InputError(
          fmt::format("{}: places elements through <use> more than {} times; keep "
                      "only the layers of the surface",
                      file_, kMostVisits));
  }

  void shape(const xmlNode* node, const Affine& ctm, const std::string& layer,
             const std::vector<std::string>& names) {
    const std::string data = path_data(node, file_);
    if (data.empty()) return;
    PathCollector collector(ctm, tolerance_);
    try {
      svgpp::value_parser<svgpp::tag::type::path_data>::parse(
          svgpp::tag::attribute::d(), collector, data, svgpp::tag::source::attribute());
    } catch (const std::exception&) {
      throw InputError(fmt::format("{}: {} has path data curdle cannot read: \"{}\"", file_,
                                   name_of(node), data.substr(0, 200)));
    }
    std::vector<std::string> also = names;
    for (const char* key : {"label", "id"}) {
      const std::string own =
          key[0] == 'l' ? attribute(node, key, kInkscape) : attribute(node, key);
      if (!own.empty()) also.push_back(own);
    }
    for (auto& [path, closed] : collector.paths) {
      for (const ContourVertex& v : path)
        if (!std::isfinite(v.x) || !std::isfinite(v.y))
          throw InputError(
              fmt::format("{}: {} has coordinates that are not finite", file_, name_of(node)));
      if (drawing_.shapes.size() >= kMostShapes || (vertices_ += path.size()) > kMostVertices)
        throw InputError(
            fmt::format("{}: holds more than {} shapes or {} vertices, more than a "
                        "site drawing needs; keep only the layers of the surface",
                        file_, kMostShapes, kMostVertices));
      Shape s;
      s.layer = layer.empty() ? kRootLayer : layer;
      s.also = also;
      s.handle = shown_name(attribute(node, "id"));
      if (s.handle.empty()) s.handle = fmt::format("line {}", xmlGetLineNo(node));
      s.entity = reinterpret_cast<const char*>(node->name);
      s.path = std::move(path);
      s.closed = closed;
      drawing_.shapes.push_back(std::move(s));
    }
  }

 public:
  size_t unresolved_ = 0;

 private:
  std::string file_;
  double tolerance_;
  Drawing& drawing_;
  std::map<std::string, const xmlNode*> ids_;
  size_t elements_ = 0, vertices_ = 0, visits_ = 0;
  bool inkscape_layers_ = false;
};

// Millimetres per unit of a length such as "140mm"; 0 for px, unitless or unknown units.
double length_mm(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || !std::isfinite(value) || value <= 0) return 0;
  const std::string unit(end);
  if (unit == "mm") return 1;
  if (unit == "cm") return 10;
  if (unit == "in") return 25.4;
  if (unit == "pt") return 25.4 / 72;
  if (unit == "pc") return 25.4 / 6;
  return 0;
}

struct DocumentDeleter {
  void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};

}  // namespace

Drawing read_svg(std::string_view bytes, const std::string& file_name, const SvgReading& reading) {
  if (bytes.size() > kMostDrawingBytes)
    throw InputError(fmt::format("{}: is {} MiB; a site drawing may be at most {} MiB", file_name,
                                 bytes.size() >> 20, kMostDrawingBytes >> 20));
  if (bytes.find("<svg") == std::string_view::npos)
    throw InputError(file_name +
                     ": is not an SVG drawing (no <svg> element); export the drawing "
                     "as SVG");
  // Elements counted in the bytes before libxml2 builds a tree of them (a 60 MB file of empty
  // groups made a tree of 2 GB): every tag but a closing one is at most an element.
  const auto tags = static_cast<size_t>(std::count(bytes.begin(), bytes.end(), '<'));
  size_t closing = 0;
  for (size_t at = bytes.find("</"); at != std::string_view::npos; at = bytes.find("</", at + 2))
    ++closing;
  if (tags - closing > 4 * kMostShapes)
    throw InputError(
        fmt::format("{}: holds {} elements, more than the {} a site drawing needs; "
                    "keep only the layers of the surface",
                    file_name, tags - closing, 4 * kMostShapes));
  // Entity declarations can make a small file expand without bound: a drawing needs none.
  if (bytes.find("<!ENTITY") != std::string_view::npos)
    throw InputError(file_name +
                     ": declares XML entities, which an SVG drawing does not need; "
                     "export it again as plain SVG");
  std::unique_ptr<xmlDoc, DocumentDeleter> doc(
      xmlReadMemory(bytes.data(), static_cast<int>(bytes.size()), "drawing.svg", nullptr,
                    XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING));
  const xmlNode* root = doc ? xmlDocGetRootElement(doc.get()) : nullptr;
  if (!root || !is_svg(root, "svg")) {
    const xmlError* e = xmlGetLastError();
    std::string why = e && e->message ? e->message : "";
    while (!why.empty() && std::isspace(static_cast<unsigned char>(why.back())))
      why.pop_back();  // libxml2 ends its messages with a newline
    throw InputError(fmt::format("{}: is not an SVG drawing{}; export the drawing as SVG",
                                 file_name,
                                 !why.empty() ? fmt::format(" (line {}: {})", e->line, why)
                                              : std::string(" (its root is no <svg>)")));
  }
  // Units: the root's width over its viewBox's, y turned up about the viewBox's bottom edge.
  double width = 0, height = 0;
  const double unit = length_mm(attribute(root, "width"), width);
  length_mm(attribute(root, "height"), height);
  const std::array<double, 4> box =
      view_box(root, file_name).value_or(std::array<double, 4>{0, 0, width, height});
  Drawing drawing;
  drawing.format = "SVG";
  double per_unit = 0;  // mm per user unit, as the drawing says
  if (unit > 0 && box[2] > 0) {
    per_unit = unit * width / box[2];
    drawing.unit_mm = 1;
    drawing.unit_name = "mm";
  }
  // Coordinates leave in mm where the drawing says its units, else in user units.
  const double scale = reading.unit_mm > 0 ? 1 : (per_unit > 0 ? per_unit : 1);
  const double mm = reading.unit_mm > 0 ? reading.unit_mm : (per_unit > 0 ? 1 : 0);
  const Affine page{scale, 0, 0, -scale, -box[0] * scale, (box[1] + box[3]) * scale};
  Walker walker(file_name, reading.chord_tolerance_mm / (mm > 0 ? mm : 1), drawing);
  walker.index(root, 0);
  walker.find_layers(root);
  walker.walk(root, page.after(Affine{}), "", {}, 0, 0);
  if (walker.unresolved_)
    drawing.notes.push_back(
        fmt::format("{} <use> elements refer to nothing in the drawing, "
                    "passed over",
                    walker.unresolved_));
  if (per_unit > 0 && reading.unit_mm == 0)
    drawing.notes.push_back(
        fmt::format("{} is {} x {} mm (its width and height) over a viewBox of "
                    "{} x {}: a user unit is {:g} mm",
                    file_name, width * unit, height * unit, box[2], box[3], per_unit));
  return drawing;
}

}  // namespace curdle::site
