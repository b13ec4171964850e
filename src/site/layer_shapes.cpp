#include "site/layer_shapes.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <unordered_map>

#include "curdle/stop.h"
#include "layout/zone.h"
#include "site/site.h"

namespace curdle::site {
namespace {

// How far from its origin a drawing's point may lie, in its units: 10^12 mm is the distance to
// the sun; a national grid's origin in millimetres is 10^10 away at most.
constexpr double kFarthest = 1e12;
// The largest bulge a drawing may give: an arc just short of a full turn (359.9°) has 4,600.
constexpr double kSteepest = 1e6;

struct Piece {
  const Shape* shape;
  Contour path;
};

// Joins open pieces end to end (within `tolerance`, drawing units) into closed contours; a chain
// that does not close is returned in `open`, its ends the gap's.
void join(std::vector<Piece> pieces, double tolerance, std::vector<Closed>& closed,
          std::vector<Closed>& open) {
  const double cell = std::max(tolerance, 1e-12) * 2;
  using Key = std::pair<int64_t, int64_t>;
  struct KeyHash {
    size_t operator()(const Key& k) const {
      return std::hash<int64_t>()(k.first * 73856093) ^ std::hash<int64_t>()(k.second * 19349663);
    }
  };
  auto key_of = [&](double x, double y) {
    return Key{static_cast<int64_t>(std::floor(x / cell)),
               static_cast<int64_t>(std::floor(y / cell))};
  };
  // Each cell's piece ends in the drawing's order (piece * 2 + 0 start, 1 end), with the used
  // ones at its front skipped for good, so that a search does not walk them again.
  struct Cell {
    std::vector<size_t> ends;
    size_t begin = 0;
  };
  std::unordered_map<Key, Cell, KeyHash> cells;
  for (size_t i = 0; i < pieces.size(); ++i) {
    cells[key_of(pieces[i].path.front().x, pieces[i].path.front().y)].ends.push_back(2 * i);
    cells[key_of(pieces[i].path.back().x, pieces[i].path.back().y)].ends.push_back(2 * i + 1);
  }
  std::vector<bool> used(pieces.size(), false);
  auto use = [&](size_t piece) { used[piece] = true; };
  // The nearest free end within the tolerance; of ends heaped in one cell (a hostile drawing's
  // thousands of lines through one point) the first 256 are looked at, an exact match at once.
  auto find_near = [&](const ContourVertex& v) -> std::optional<size_t> {
    const Key k = key_of(v.x, v.y);
    std::optional<size_t> best;
    double nearest = tolerance;
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy) {
        const auto found = cells.find(Key{k.first + dx, k.second + dy});
        if (found == cells.end()) continue;
        Cell& near = found->second;
        while (near.begin < near.ends.size() && used[near.ends[near.begin] / 2]) ++near.begin;
        const size_t last = std::min(near.ends.size(), near.begin + 256);
        for (size_t j = near.begin; j < last; ++j) {
          if (used[near.ends[j] / 2]) continue;
          const Contour& p = pieces[near.ends[j] / 2].path;
          const ContourVertex& e = near.ends[j] % 2 ? p.back() : p.front();
          const double d = std::hypot(e.x - v.x, e.y - v.y);
          if (d <= nearest) nearest = d, best = near.ends[j];
          if (d == 0) return best;
        }
      }
    return best;
  };
  for (size_t first = 0; first < pieces.size(); ++first) {
    stop_point();
    if (used[first]) continue;
    use(first);
    Closed c{pieces[first].path,
             handle_of(*pieces[first].shape),
             pieces[first].shape->entity,
             pieces[first].shape->insert,
             {pieces[first].shape}};
    const size_t most_pieces = 100000;
    for (size_t k = 0; k < most_pieces; ++k) {
      const ContourVertex start = c.path.front(), end = c.path.back();
      if (c.path.size() > 2 && std::hypot(start.x - end.x, start.y - end.y) <= tolerance) break;
      const auto next = find_near(end);
      if (!next) break;
      use(*next / 2);
      const Piece& p = pieces[*next / 2];
      Contour add = *next % 2 ? reversed(p.path) : p.path;
      c.path.back().bulge = add.front().bulge;  // the shared vertex carries the next edge
      c.path.insert(c.path.end(), add.begin() + 1, add.end());
      c.handles += ", " + handle_of(*p.shape);
      c.shapes.push_back(p.shape);
    }
    const ContourVertex start = c.path.front(), end = c.path.back();
    const bool closes =
        c.path.size() > 2 && std::hypot(start.x - end.x, start.y - end.y) <= tolerance;
    if (closes) {
      c.path.pop_back();  // the last vertex is the first again
      closed.push_back(std::move(c));
    } else {
      open.push_back(std::move(c));
    }
  }
}

// The outer shapes found so far, by where their boxes lie, so that a shape is tested only
// against those whose box may hold it (the box holding its box's centre): a layer of 190,000
// pits is sorted in linear time, not in 190,000 squared box tests.
class OuterGrid {
 public:
  OuterGrid(const std::vector<Rect>& boxes, double tolerance) : tolerance_(tolerance) {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const Rect& b : boxes)
      x0 = std::min(x0, b.x), y0 = std::min(y0, b.y), x1 = std::max(x1, b.right()),
      y1 = std::max(y1, b.top());
    const auto side = static_cast<size_t>(
        std::clamp(std::ceil(std::sqrt(static_cast<double>(boxes.size()))), 1.0, 1024.0));
    n_ = side;
    x0_ = x0, y0_ = y0;
    w_ = x1 > x0 ? (x1 - x0) / static_cast<double>(side) : 1;
    h_ = y1 > y0 ? (y1 - y0) / static_cast<double>(side) : 1;
    cells_.resize(side * side);
  }
  // The outer shape `seq` (its place among the outer shapes) whose box is `b`.
  void add(size_t seq, const Rect& b) {
    const size_t cx0 = column(b.x - tolerance_), cx1 = column(b.right() + tolerance_);
    const size_t cy0 = row(b.y - tolerance_), cy1 = row(b.top() + tolerance_);
    if ((cx1 - cx0 + 1) * (cy1 - cy0 + 1) > 256) return wide_.push_back(seq);
    for (size_t y = cy0; y <= cy1; ++y)
      for (size_t x = cx0; x <= cx1; ++x) cells_[y * n_ + x].push_back(seq);
  }
  // The outer shapes whose box may hold `b`, in the order they were added.
  std::vector<size_t> near(const Rect& b) const {
    const std::vector<size_t>& cell = cells_[row(b.y + b.h / 2) * n_ + column(b.x + b.w / 2)];
    std::vector<size_t> out;
    std::merge(cell.begin(), cell.end(), wide_.begin(), wide_.end(), std::back_inserter(out));
    return out;
  }

 private:
  size_t column(double x) const { return index((x - x0_) / w_); }
  size_t row(double y) const { return index((y - y0_) / h_); }
  size_t index(double v) const {
    return static_cast<size_t>(std::clamp(std::floor(v), 0.0, static_cast<double>(n_ - 1)));
  }

  double tolerance_;
  size_t n_ = 1;
  double x0_ = 0, y0_ = 0, w_ = 1, h_ = 1;
  std::vector<std::vector<size_t>> cells_;
  std::vector<size_t> wide_;  // boxes over more than 256 cells, tested for every shape
};

// Whether every vertex of `inner` lies inside `outer` or on its edges.
bool lies_within(const Polygon& inner, const Polygon& outer, double tolerance) {
  return std::all_of(inner.begin(), inner.end(), [&](const auto& v) {
    return contains(outer, v[0], v[1]) || distance_to_edges(outer, v[0], v[1]) <= tolerance;
  });
}

Rect bounds_of(const Polygon& p) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& v : p)
    x0 = std::min(x0, v[0]), y0 = std::min(y0, v[1]), x1 = std::max(x1, v[0]),
    y1 = std::max(y1, v[1]);
  return {x0, y0, x1 - x0, y1 - y0};
}

}  // namespace

// 14000 as "14,000"; 2.5 as "2.5".
std::string grouped(double v) {
  if (std::fabs(v - std::round(v)) > 1e-6) return fmt::format("{:g}", v);
  // Grouped by hand, appended piece by piece (GCC 12 warns falsely on insert and +).
  const std::string digits = fmt::format("{:.0f}", std::fabs(std::round(v)));
  std::string out = v < 0 ? "-" : "";
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

Contour reversed(const Contour& path) {
  // The edge a → b with bulge k is b → a with bulge -k: each bulge moves to the edge's other end.
  Contour r(path.rbegin(), path.rend());
  for (size_t i = 0; i + 1 < r.size(); ++i) r[i].bulge = -r[i + 1].bulge;
  r.back().bulge = 0;
  return r;
}

// "LINE 9D in block \"PIT\" (INSERT 2F)": where a designer finds it in CAD.
std::string handle_of(const Shape& s) {
  std::string name = s.handle.empty() ? s.entity : s.entity + " " + s.handle;
  if (!s.block.empty()) name += fmt::format(" in block \"{}\"", s.block);
  if (!s.insert_handle.empty()) name += fmt::format(" (INSERT {})", s.insert_handle);
  return name;
}

// A number at the drawing's precision, without trailing zeros: 530012.3456 m stays so.
std::string number_text(double v, int precision) {
  std::string t = fmt::format("{:.{}f}", v, std::clamp(precision, 0, 8));
  if (t.find('.') != std::string::npos) {
    while (t.back() == '0') t.pop_back();
    if (t.back() == '.') t.pop_back();
  }
  return t == "-0" ? "0" : t;
}

std::string point_text(const ContourVertex& v, int precision) {
  return fmt::format("({}, {})", number_text(v.x, precision), number_text(v.y, precision));
}

// A layer's closed contours, as a designer means them: closed shapes, and open pieces joined
// end to end. A piece left open is the strip it covers where it was drawn with width; else it
// is passed over where it lies inside one of the layer's closed contours, and refused where it
// does not. A closed contour inside another of the layer's, or the same again, is passed over:
// the layer's shapes are the outer ones.
std::vector<Closed> closed_on(const Drawing& drawing, const std::string& layer, double tolerance,
                              const std::string& file, const std::string& role, double unit_mm,
                              PassedOver& passed) {
  std::vector<Closed> closed;
  std::vector<Piece> pieces;
  for (const Shape& s : drawing.shapes) {
    if (!on_layer(s, layer)) continue;
    if (!s.fault.empty())
      throw InputError(fmt::format(
          "{}: {}{} (the layer holds the {})", file, s.fault,
          s.insert_handle.empty() ? "" : ", placed by INSERT " + s.insert_handle, role));
    for (const ContourVertex& v : s.path)
      if (!(std::fabs(v.x) <= kFarthest && std::fabs(v.y) <= kFarthest &&
            std::fabs(v.bulge) <= kSteepest))
        throw InputError(
            fmt::format("{}: the {} on layer \"{}\" has the point ({:g}, {:g}), "
                        "beyond {:g} drawing units from the origin or not a number; "
                        "the drawing is damaged: export it again",
                        file, handle_of(s), layer, v.x, v.y, kFarthest));
    if (s.closed)
      closed.push_back({s.path, handle_of(s), s.entity, s.insert, {&s}});
    else
      pieces.push_back({&s, s.path});
  }
  std::vector<Closed> open;
  join(std::move(pieces), tolerance, closed, open);
  std::vector<Closed> still_open;
  for (Closed& o : open) {
    const bool wide = std::all_of(o.shapes.begin(), o.shapes.end(),
                                  [](const Shape* s) { return !s->strip.empty(); });
    if (!wide) {
      still_open.push_back(std::move(o));
      continue;
    }
    for (const Shape* s : o.shapes)
      closed.push_back({s->strip, handle_of(*s) + " (its width)", s->entity, s->insert, {s}});
  }

  // The outer shapes: each tested against the larger ones whose box holds it.
  std::vector<Polygon> flat;
  std::vector<double> area;
  std::vector<Rect> box;
  for (const Closed& c : closed) {
    flat.push_back(flatten(c.path, tolerance));
    area.push_back(polygon_area(flat.back()));
    box.push_back(bounds_of(flat.back()));
  }
  std::vector<size_t> order(closed.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  // Largest first; of equal shapes the one drawn as an outline before its hatch.
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (std::fabs(area[a] - area[b]) > 1e-9 * std::max(area[a], area[b])) return area[a] > area[b];
    return (closed[a].entity != "HATCH") > (closed[b].entity != "HATCH");
  });
  auto holds = [&](size_t outer, size_t inner) {
    const Rect& o = box[outer];
    const Rect& i = box[inner];
    return i.x >= o.x - tolerance && i.y >= o.y - tolerance && i.right() <= o.right() + tolerance &&
           i.top() <= o.top() + tolerance && lies_within(flat[inner], flat[outer], tolerance);
  };
  std::vector<size_t> outer;
  OuterGrid grid(box, tolerance);
  for (size_t i : order) {
    stop_point();
    bool nested = false, repeat = false;
    for (size_t seq : grid.near(box[i])) {
      const size_t o = outer[seq];
      if (holds(o, i)) {
        nested = true;
        repeat = std::fabs(area[o] - area[i]) <= 1e-6 * area[o] && holds(i, o);
        break;
      }
    }
    if (!nested) {
      grid.add(outer.size(), box[i]);
      outer.push_back(i);
    } else if (repeat) {
      ++passed.repeats;
    } else {
      ++passed.inside;
    }
  }
  for (const Closed& o : still_open) {
    stop_point();
    Polygon chain;
    for (const ContourVertex& v : o.path) chain.push_back({v.x, v.y});
    const std::vector<size_t> near = grid.near(bounds_of(chain));
    const bool within = std::any_of(near.begin(), near.end(), [&](size_t seq) {
      return lies_within(chain, flat[outer[seq]], tolerance);
    });
    if (within) {
      passed.pieces += o.shapes.size();
      continue;
    }
    throw InputError(fmt::format(
        "{}: the {} on layer \"{}\" is not closed: {} ends at {} and {} ({} mm apart, more than "
        "the {:g} mm that are joined); close it (PEDIT Join, or draw it as one closed polyline)",
        file, role, layer, o.handles, point_text(o.path.front(), drawing.precision),
        point_text(o.path.back(), drawing.precision),
        grouped(std::hypot(o.path.front().x - o.path.back().x, o.path.front().y - o.path.back().y) *
                unit_mm),
        kJoinTolerance));
  }
  std::sort(outer.begin(), outer.end());  // in the drawing's order
  std::vector<Closed> kept;
  for (size_t i : outer) kept.push_back(std::move(closed[i]));
  return kept;
}

// "3 shapes inside others on layer L-PLNT-PITS passed over (...)": what a layer held besides
// its shapes.
void note_passed_over(const PassedOver& p, const std::string& layer,
                      std::vector<std::string>& notes) {
  if (p.inside)
    notes.push_back(
        fmt::format("layer \"{}\": {} closed shapes inside others passed over (a "
                    "trunk in its pit, a sash in its frame): the outer line is the "
                    "shape",
                    layer, p.inside));
  if (p.pieces)
    notes.push_back(
        fmt::format("layer \"{}\": {} lines and arcs inside its shapes passed over "
                    "(grilles, glazing bars)",
                    layer, p.pieces));
  if (p.repeats)
    notes.push_back(
        fmt::format("layer \"{}\": {} shapes drawn again over another (a hatch "
                    "over its boundary) read once",
                    layer, p.repeats));
}

// The smallest of a layer's shapes around a point in drawing coordinates, as CAD's BOUNDARY
// picks; InputError naming the point when none lies around it.
Closed smallest_around(const std::vector<Closed>& shapes, const std::array<double, 2>& point,
                       double tolerance, const std::string& file, const std::string& layer,
                       int precision) {
  std::optional<size_t> best;
  double smallest = 0;
  for (size_t i = 0; i < shapes.size(); ++i) {
    const Polygon p = flatten(shapes[i].path, tolerance);
    const double a = polygon_area(p);
    if (contains(p, point[0], point[1]) && (!best || a < smallest)) best = i, smallest = a;
  }
  if (!best)
    throw InputError(fmt::format(
        "{}: no closed shape on layer \"{}\" lies around the point ({}, "
        "{}) that around gives (drawing coordinates)",
        file, layer, number_text(point[0], precision), number_text(point[1], precision)));
  return shapes[*best];
}

}  // namespace curdle::site
