// Layouts: geometry adds up, counts match the overlay, the SVG parses in a real XML parser
// (expat) and says what the layout holds, mix and keep colour as described.
#include <expat.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "curdle/curdling.h"
#include "curdle/overlay.h"
#include "curdle/palette.h"
#include "export/layout_png.h"
#include "export/svg.h"
#include "kinds/perforation.h"
#include "layout/builder.h"
#include "layout/piece.h"
#include "layout/zone.h"
#include "test_support.h"

namespace curdle {
using test::design;

namespace {

// The floor or wall of `spec` laid from a field of exactly its elements, curdled with `seed`.
Layout lay_floor(const Design& d, const LayoutSpec& spec, uint64_t seed) {
  Design sized = d;
  const auto cells = elements_to_cover(spec);
  sized.field.size = {cells[0], cells[1], 1};
  return make_layout(sized, curdle(sized, seed, sized.field), sized.field, spec);
}

double intersection(const Rect& a, const Rect& b) {
  const double w = std::min(a.right(), b.right()) - std::max(a.x, b.x);
  const double h = std::min(a.top(), b.top()) - std::max(a.y, b.y);
  return w > 0 && h > 0 ? w * h : 0;
}

struct SvgSummary {
  std::map<int, uint64_t> counts;  // value -> elements, from data-count
  std::set<std::string> ids;
  std::set<std::string> classes;
  std::string width, height, view_box;
  int patterns = 0, pattern_parts = 0;
  std::map<int, std::string> fills;
};

SvgSummary parse_svg(const std::string& text) {
  SvgSummary s;
  struct State {
    SvgSummary* s;
    int value = -1;
    int depth = 0, value_depth = -1;
  } state{&s};
  XML_Parser p = XML_ParserCreate("UTF-8");
  XML_SetUserData(p, &state);
  XML_SetElementHandler(
      p,
      [](void* data, const XML_Char* name, const XML_Char** attrs) {
        auto* st = static_cast<State*>(data);
        ++st->depth;
        std::map<std::string, std::string> a;
        for (int i = 0; attrs[i]; i += 2) a[attrs[i]] = attrs[i + 1];
        const std::string tag = name;
        if (tag == "svg")
          st->s->width = a["width"], st->s->height = a["height"], st->s->view_box = a["viewBox"];
        if (a.count("id")) {
          EXPECT_TRUE(st->s->ids.insert(a["id"]).second) << "duplicate id " << a["id"];
        }
        if (a.count("class")) st->s->classes.insert(a["class"]);
        if (tag == "pattern") ++st->s->patterns;
        if (tag == "rect" && st->depth == 4 && st->s->patterns > 0 && st->value < 0)
          ++st->s->pattern_parts;
        if (tag == "g" && a["class"] == "value") {
          st->value = std::stoi(a["data-value"]);
          st->value_depth = st->depth;
          st->s->fills[st->value] = a["fill"];
        } else if (st->value >= 0 && a.count("data-count")) {
          st->s->counts[st->value] += std::stoull(a["data-count"]);
        }
      },
      [](void* data, const XML_Char*) {
        auto* st = static_cast<State*>(data);
        if (st->depth == st->value_depth) st->value = -1, st->value_depth = -1;
        --st->depth;
      });
  EXPECT_EQ(XML_Parse(p, text.data(), static_cast<int>(text.size()), 1), XML_STATUS_OK)
      << XML_ErrorString(XML_GetErrorCode(p)) << " at line " << XML_GetCurrentLineNumber(p);
  XML_ParserFree(p);
  return s;
}

std::string svg_of(const Layout& built) {
  Layout layout = built;
  layout.source.description = "a <test> & more";  // the title block escapes it
  layout.source.seed = 1;
  std::ostringstream out;
  write_layout_svg(out, layout);
  return out.str();
}

}  // namespace

TEST(Geometry, SubtractKeepsExactlyWhatNoHoleCovers) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 100);
  for (int trial = 0; trial < 300; ++trial) {
    const Rect a{u(rng), u(rng), 1 + u(rng), 1 + u(rng)};
    // Disjoint holes: cells of a coarse grid, so their areas simply add.
    std::vector<Rect> holes;
    std::set<std::pair<int, int>> used;
    for (int i = 0; i < 4; ++i) {
      const int gx = static_cast<int>(u(rng) / 25), gy = static_cast<int>(u(rng) / 25);
      if (used.insert({gx, gy}).second)
        holes.push_back(Rect{gx * 50.0, gy * 50.0, 10 + u(rng) / 4, 10 + u(rng) / 4});
    }
    const auto pieces = subtract(a, holes);
    double kept = 0, covered = 0;
    for (const Rect& p : pieces) {
      kept += p.area();
      EXPECT_NEAR(intersection(p, a), p.area(), 1e-9);
      for (const Rect& h : holes) EXPECT_NEAR(intersection(p, h), 0, 1e-9);
    }
    for (size_t i = 0; i < pieces.size(); ++i)
      for (size_t j = i + 1; j < pieces.size(); ++j)
        EXPECT_NEAR(intersection(pieces[i], pieces[j]), 0, 1e-9);
    for (const Rect& h : holes) covered += intersection(a, h);
    EXPECT_NEAR(kept + covered, a.area(), 1e-6);
  }
}

TEST(Geometry, MergedRunsCoverEveryCellOnce) {
  std::mt19937 rng(5);
  const int64_t rows = 37, cols = 53;
  std::vector<int> grid(rows * cols);
  for (auto& v : grid) v = static_cast<int>(rng() % 4) - 1;  // -1: not merged
  std::vector<int> seen(grid.size(), 0);
  for (const GridRect& g : merge_runs(grid, rows, cols))
    for (int64_t r = g.row0; r <= g.row1; ++r)
      for (int64_t c = g.column0; c <= g.column1; ++c) {
        EXPECT_EQ(grid[r * cols + c], g.value);
        ++seen[r * cols + c];
      }
  for (size_t i = 0; i < grid.size(); ++i) EXPECT_EQ(seen[i], grid[i] >= 0 ? 1 : 0);
}

TEST(Layout, CountsPerValueMatchTheOverlay) {
  const Design d = design(4, 2, {{"3/4", "2/3"}, {"1/2", "1/2"}});
  const CurdField f = curdle(d, 4, d.field);
  LayoutSpec spec = test::layout_spec();
  spec.joint = 5;
  const Layout layout = make_layout(d, f, d.field, spec);
  ASSERT_EQ(layout.elements.size(), 256u);
  const auto counts = value_counts(f);
  for (uint32_t v = 0; v < 4; ++v) EXPECT_EQ(layout.legend[v].count, counts[v]);
  SvgSummary svg = parse_svg(svg_of(layout));
  for (uint32_t v = 0; v < 4; ++v) EXPECT_EQ(svg.counts[v], counts[v]) << "value " << v;
  EXPECT_EQ(svg.width, "5200mm");  // 16 x 305 - 5 = 4875, and a margin of 4875 / 30 each side
  EXPECT_EQ(svg.view_box.rfind("0 0 5200 ", 0), 0u);
  EXPECT_TRUE(svg.ids.count("legend") && svg.ids.count("title-block") && svg.ids.count("joints"));
}

TEST(Layout, AreasAddUpForEveryOriginCornerWithCutsAndOpenings) {
  const Design d = design(4, 2, {{"3/4", "1/2", "2/3"}});
  for (Corner corner :
       {Corner::bottom_left, Corner::bottom_right, Corner::top_left, Corner::top_right}) {
    for (const std::string kind : {"paving", "facade"})
      for (double bond : {0.0, 0.5, 1.0 / 3, 0.25}) {
        const std::array<double, 2> shift =
            kind == "facade" ? std::array<double, 2>{130, 80} : std::array<double, 2>{0, 0};
        LayoutSpec spec = test::layout_spec();
        spec.set_kind(layout_kind(kind));
        spec.origin = corner;
        spec.shift = shift;
        spec.bond = bond;
        spec.module_w = 600, spec.module_h = 300, spec.joint = 10;
        spec.size = std::array<double, 2>{18000, 15600};
        if (kind == "facade")
          spec.own<FacadeKeys>().openings = {{1200, 0, 7200, 2700},
                                             {1500, 3900, 1200, 1500},
                                             {16200, 12900, 1200, 1500},
                                             {17500, 14000, 500, 1600}};
        const Layout layout = lay_floor(d, spec, 9);
        double elements = 0, openings = 0;
        for (const Element& e : layout.elements) {
          elements += e.area();
          for (const Rect& r : e.shape) {
            EXPECT_NEAR(intersection(r, e.nominal), r.area(), 1e-6) << e.id;  // inside its module
            EXPECT_NEAR(intersection(r, Rect{0, 0, 18000, 15600}), r.area(), 1e-6) << e.id;
            for (const Rect& o : layout.openings) EXPECT_NEAR(intersection(r, o), 0, 1e-6) << e.id;
          }
          EXPECT_EQ(e.cut, e.area() < 600 * 300 - 1e-6);
        }
        for (const Rect& o : layout.openings) openings += o.area();
        EXPECT_NEAR(elements + joint_area(layout) + openings, 18000.0 * 15600.0, 1e-3)
            << static_cast<int>(corner) << " " << kind << " bond " << bond;
        EXPECT_EQ(layout.elements.size() + layout.omitted,
                  static_cast<size_t>(layout.columns * layout.rows));
        // The element IDs follow the laying order from the origin corner: row 0, column 0 sits
        // there.
        const Element& first = layout.elements.front();
        EXPECT_EQ(first.row, 0);
        const bool right = corner == Corner::bottom_right || corner == Corner::top_right;
        const bool top = corner == Corner::top_left || corner == Corner::top_right;
        if (first.column == 0) {  // the grid starts the shift back from the corner
          EXPECT_NEAR(right ? 18000 - first.nominal.right() : first.nominal.x, -shift[0], 1e-6);
          EXPECT_NEAR(top ? 15600 - first.nominal.top() : first.nominal.y, -shift[1], 1e-6);
        }
        SvgSummary svg = parse_svg(svg_of(layout));
        uint64_t drawn = 0;
        for (auto& [v, n] : svg.counts) drawn += n;
        EXPECT_EQ(drawn, layout.elements.size());
      }
  }
}

// Each course is moved along by the bond's share of the pitch from the course below, counted
// from the origin corner; every element still stands for its own cell.
TEST(Layout, CoursesAreOffsetByTheBond) {
  const Design d = design(4, 2, {{"3/4", "1/2", "2/3"}});
  for (Corner corner : {Corner::bottom_left, Corner::top_right})
    for (double bond : {0.5, 1.0 / 3, 0.25}) {
      LayoutSpec spec = test::layout_spec();
      spec.set_kind(layout_kind("facade"));
      spec.origin = corner;
      spec.bond = bond;
      spec.module_w = 215, spec.module_h = 65, spec.joint = 10;
      spec.size = std::array<double, 2>{5000, 3000};
      const Layout layout = lay_floor(d, spec, 3);
      const bool right = from_right(corner);
      std::map<int64_t, double> start;  // per course: where its column 1 begins, from the corner
      std::set<std::pair<int64_t, int64_t>> cells_used;
      for (const Element& e : layout.elements) {
        EXPECT_TRUE(cells_used.insert({e.cell_x, e.cell_y}).second) << e.id;
        if (e.column == 1) start[e.row] = right ? 5000 - e.nominal.right() : e.nominal.x;
      }
      ASSERT_GT(start.size(), 10u);
      for (const auto& [row, at] : start) {
        if (!start.count(row + 1)) continue;
        const double moved = at - start.at(row + 1);  // the course above starts this much earlier
        const double share = moved / 225 - std::floor(moved / 225 + 1e-9);  // of the pitch
        EXPECT_NEAR(share, bond, 1e-9) << "bond " << bond << " row " << row;
      }
    }
}

// layout.origin = "centre": the cut pieces at opposite edges are equal.
TEST(Layout, ACentredGridCutsOppositeEdgesEqually) {
  const Design d = design(4, 2, {{"3/4", "1/2", "2/3"}});
  for (const auto& [w, h] : {std::pair{7000.0, 4330.0}, {12000.0, 8000.0}, {6000.0, 3010.0}}) {
    LayoutSpec spec = test::layout_spec();
    spec.set_kind(layout_kind("paving"));
    spec.module_w = 600, spec.module_h = 300, spec.joint = 10;
    spec.size = std::array<double, 2>{w, h};
    spec.centred = true;
    spec.shift = {centring_shift(w, 600, 10), centring_shift(h, 300, 10)};
    const Layout layout = lay_floor(d, spec, 3);
    double left = 1e9, right = 1e9, bottom = 1e9, top = 1e9;
    for (const Element& e : layout.elements) {
      const Rect& r = e.shape.front();
      if (r.x < 1e-6) left = std::min(left, r.w);
      if (r.right() > w - 1e-6) right = std::min(right, r.w);
      if (r.y < 1e-6) bottom = std::min(bottom, r.h);
      if (r.top() > h - 1e-6) top = std::min(top, r.h);
    }
    EXPECT_NEAR(left, right, 1e-6) << w;
    EXPECT_NEAR(bottom, top, 1e-6) << h;
    EXPECT_GE(left, 300 - 1e-6) << "centred, no end piece is less than half an element";
  }
}

TEST(Layout, MixBlendsOrTakesTheGivenColoursAndKeepShowsEachCurd) {
  Design d = design(4, 2, {{"3/4", "3/4"}, {"3/4", "3/4"}});
  d.curds[0].colour = Rgb{200, 0, 0};
  d.curds[1].colour = Rgb{0, 0, 200};
  const CurdField f = curdle(d, 2, d.field);
  LayoutSpec mix = test::layout_spec();
  mix.module_w = mix.module_h = 100;
  const Layout mixed = make_layout(d, f, d.field, mix);
  EXPECT_EQ(mixed.legend[3].colour, (Rgb{100, 0, 100}));  // red and blue give purple
  mix.value_colours = {Rgb{1, 1, 1}, std::nullopt, Rgb{3, 3, 3}, Rgb{4, 4, 4}};
  const Layout given = make_layout(d, f, d.field, mix);
  EXPECT_EQ(given.legend[3].colour, (Rgb{4, 4, 4}));
  EXPECT_EQ(given.legend[1].colour, (Rgb{200, 0, 0}));
  EXPECT_EQ(parse_svg(svg_of(given)).fills[3], "#040404");

  LayoutSpec keep = mix;
  keep.combine = Combine::keep;
  keep.value_colours.clear();
  const Layout kept = make_layout(d, f, d.field, keep);
  ASSERT_EQ(kept.legend[3].parts.size(), 2u);
  EXPECT_EQ(kept.legend[3].parts[0], (Rgb{200, 0, 0}));
  EXPECT_EQ(kept.legend[3].parts[1], (Rgb{0, 0, 200}));
  SvgSummary svg = parse_svg(svg_of(kept));
  EXPECT_EQ(svg.patterns, 4);
  EXPECT_EQ(svg.fills[3], "url(#parts-3)");
  // The PNG shows both curds in a cell of value 3: red on the left, blue on the right.
  Layout drawn = kept;
  drawn.drawing.scale = 1, drawn.drawing.dpi = 25.4;  // one pixel per millimetre
  const PreviewImage png = render_layout(drawn);
  for (const Element& e : kept.elements) {
    if (e.value != 3) continue;
    auto at = [&](double x, double y) {
      const size_t px = static_cast<size_t>(x), py = static_cast<size_t>(kept.height - y);
      const uint8_t* p = &png.rgb[(py * png.width + px) * 3];
      return Rgb{p[0], p[1], p[2]};
    };
    EXPECT_EQ(at(e.nominal.x + 20, e.nominal.y + 50), (Rgb{200, 0, 0}));
    EXPECT_EQ(at(e.nominal.x + 80, e.nominal.y + 50), (Rgb{0, 0, 200}));
    break;
  }
}

TEST(Layout, PngColoursEachElementAndRecordsItsScale) {
  const Design d = design(4, 2, {{"3/4", "2/3"}});
  const CurdField f = curdle(d, 8, d.field);
  LayoutSpec spec = test::layout_spec();
  spec.joint = 20;
  Layout layout = make_layout(d, f, d.field, spec);
  EXPECT_EQ(drawing_scale(layout), 20);                 // 5.1 m fits an A3 sheet at 1:20
  layout.drawing.scale = 10, layout.drawing.dpi = 254;  // 1 px = 1 mm / (254 / 25.4 / 10) = 1 mm
  const PreviewImage png = render_layout(layout);
  EXPECT_EQ(png.width, static_cast<int>(std::ceil(layout.width)));
  for (const Element& e : layout.elements) {
    const size_t px = static_cast<size_t>(e.nominal.x + 150),
                 py = static_cast<size_t>(layout.height - e.nominal.y - 150);
    const uint8_t* p = &png.rgb[(py * png.width + px) * 3];
    EXPECT_EQ((Rgb{p[0], p[1], p[2]}), layout.legend[e.value].colour) << e.id;
  }
}

TEST(Layout, OverlaysDrawTheStageGridInTheJointsAndTheWindow) {
  const Design d = design(4, 2, {{"3/4", "2/3"}});
  const CurdField f = curdle(d, 8, d.field);
  LayoutSpec spec = test::layout_spec();
  spec.joint = 10;
  spec.drawing.stage_grid = true;
  spec.drawing.highlight = Box{{4, 4, 0}, {8, 4, 1}};
  const Layout layout = make_layout(d, f, d.field, spec);
  // The stage-1 boundary between cells 3 and 4 runs in the middle of their joint.
  EXPECT_NEAR(layout.cell_edge_x(4), 4 * 310 - 5, 1e-9);
  EXPECT_NEAR(layout.cell_edge_x(0), 0, 1e-9);
  EXPECT_NEAR(layout.cell_edge_x(16), layout.width, 1e-9);
  const std::string svg = svg_of(layout);
  const SvgSummary s = parse_svg(svg);
  EXPECT_TRUE(s.ids.count("stage-grid"));
  EXPECT_TRUE(s.ids.count("window"));
  EXPECT_NE(svg.find("data-cells=\"4,4,8,4\""), std::string::npos);
  EXPECT_TRUE(s.classes.count("stage-0") && s.classes.count("stage-1"));
}

// Merged runs keep a large paving's SVG small: at most 62 bytes a tile, 60 MiB a million
// (240,000 tiles here keep the suite quick).
TEST(Layout, ALargePavingStaysSmallAsSvg) {
  Design d = design(2, 2, {std::vector<std::string>(10, "0.9")});
  d.field.size = {400, 600, 1};
  const CurdField f = curdle(d, 1, d.field);
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("paving"));
  spec.joint = 3;
  const Layout layout = make_layout(d, f, d.field, spec);
  const std::string svg = svg_of(layout);
  EXPECT_LT(svg.size(), (60u << 20) / 1000000 * 240000) << "240,000 tiles";
  SvgSummary s = parse_svg(svg);
  EXPECT_EQ(s.counts[0] + s.counts[1], 240000u);
}

}  // namespace curdle

namespace curdle {
namespace {

struct Sheet {
  Design design;
  LayoutSpec spec = test::layout_spec();
  Layout layout;
};

Sheet perforated(Combine combine, HoleFix fix, double bridge, uint64_t seed) {
  Sheet s;
  s.design = test::design(4, 2, {{"1/2", "1/2"}, {"1/2", "1/2"}, {"1/2", "1/2"}});
  s.spec.set_kind(layout_kind("perforation"));
  s.spec.combine = combine;
  s.spec.module_w = s.spec.module_h = 40;
  s.spec.size = std::array<double, 2>{640, 640};
  s.spec.own<PerforationKeys>().thickness = 2;
  s.spec.own<PerforationKeys>().holes = {{16, -7, 6}, {16, 7, 6}, {16, 0, -7}};
  s.spec.own<PerforationKeys>().min_diameter = 5;
  s.spec.own<PerforationKeys>().min_bridge = bridge;
  s.spec.own<PerforationKeys>().edge_margin = 5;
  s.spec.own<PerforationKeys>().fix = fix;
  s.spec.own<PerforationKeys>().chord_tolerance = 0.01;
  const CurdField f = curdle(s.design, seed, s.design.field);
  s.layout = make_layout(s.design, f, s.design.field, s.spec);
  return s;
}

// Parts of an opening, for checking rules independently of the builder's own bookkeeping.
std::vector<Circle> circles_of(const Element& e, const LayoutSpec& spec) {
  if (e.circle) return {*e.circle};
  std::vector<Circle> parts;
  const double cx = e.nominal.x + e.nominal.w / 2, cy = e.nominal.y + e.nominal.h / 2;
  for (size_t c = 0; c < spec.own<PerforationKeys>().holes.size(); ++c)
    if (e.value >> c & 1)
      parts.push_back({cx + spec.own<PerforationKeys>().holes[c].offset_x,
                       cy + spec.own<PerforationKeys>().holes[c].offset_y,
                       spec.own<PerforationKeys>().holes[c].diameter});
  return parts;
}

}  // namespace

// A gabled screen (layout.outline): every opening keeps the edge margin inside the outline,
// the fabrication sheets are cut to it (one wholly beyond it is not cut at all), and the open
// area is the openings over the outline's area.
TEST(Perforation, AnOutlineBoundsTheOpeningsAndCutsTheSheets) {
  Sheet s;
  s.design = test::design(4, 2, {{"3/4", "3/4"}, {"1/2", "3/4"}});
  s.spec.set_kind(layout_kind("perforation"));
  s.spec.module_w = s.spec.module_h = 40;
  s.spec.size = std::array<double, 2>{640, 640};
  s.spec.outline = {{0, 0}, {640, 0}, {640, 400}, {320, 640}, {0, 400}};
  s.spec.own<PerforationKeys>().holes = {{16, 0, 0}, {24, 0, 0}};
  s.spec.own<PerforationKeys>().edge_margin = 5;
  s.spec.own<PerforationKeys>().fix = HoleFix::drop;
  s.spec.own<PerforationKeys>().sheet_size = std::array<double, 2>{320, 320};
  const Layout layout =
      make_layout(s.design, curdle(s.design, 3, s.design.field), s.design.field, s.spec);
  ASSERT_GT(layout.elements.size(), 50u);
  double open = 0;
  for (const Element& e : layout.elements) {
    const Circle& c = *e.circle;
    open += e.area();
    // At least the margin inside every edge of the outline.
    EXPECT_TRUE(contains(s.spec.outline, c.cx, c.cy)) << e.id;
    for (size_t i = 0; i < s.spec.outline.size(); ++i) {
      const auto& a = s.spec.outline[i];
      const auto& b = s.spec.outline[(i + 1) % s.spec.outline.size()];
      const double dx = b[0] - a[0], dy = b[1] - a[1];
      const double t =
          std::clamp(((c.cx - a[0]) * dx + (c.cy - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      EXPECT_GE(std::hypot(a[0] + t * dx - c.cx, a[1] + t * dy - c.cy) - c.d / 2, 5 - 1e-9) << e.id;
    }
  }
  ASSERT_EQ(layout.sheets.size(), 4u);  // 2 x 2 sheets of 320, all meeting the gable
  double surface = 0;
  for (const auto& sheet : layout.sheets) surface += sheet.surface;
  EXPECT_NEAR(surface, polygon_area(s.spec.outline), 1e-6);
  EXPECT_FALSE(layout.sheets[2].outline.empty());  // the upper sheets follow the gable
  EXPECT_NEAR(layout.open_area, open / polygon_area(s.spec.outline), 1e-12);
}

TEST(Perforation, DroppingLeavesNoHoleTooCloseOrTooNearTheEdge) {
  for (Combine combine : {Combine::mix, Combine::keep})
    for (uint64_t seed = 1; seed <= 5; ++seed) {
      const Sheet s = perforated(combine, HoleFix::drop, 8, seed);
      const auto& holes = s.layout.elements;
      for (size_t i = 0; i < holes.size(); ++i) {
        const auto a = circles_of(holes[i], s.spec);
        for (const Circle& c : a) {
          EXPECT_GE(c.cx - c.d / 2, 5 - 1e-9);
          EXPECT_LE(c.cx + c.d / 2, 640 - 5 + 1e-9);
          EXPECT_GE(c.cy - c.d / 2, 5 - 1e-9);
          EXPECT_LE(c.cy + c.d / 2, 640 - 5 + 1e-9);
        }
        for (size_t j = i + 1; j < holes.size(); ++j)  // across cells too: every pair
          EXPECT_GE(bridge(a, circles_of(holes[j], s.spec)), 8 - 1e-9)
              << holes[i].id << " " << holes[j].id;
      }
      // Merged openings (mix) grow past their cell's spacing: an 8 mm bridge cannot hold
      // everywhere. Kept unions stay within 15 mm of the centre, 10 mm from any neighbour.
      if (combine == Combine::mix) {
        EXPECT_FALSE(s.layout.violations.empty());
      }
    }
}

TEST(Perforation, ReportingOnlyChangesNothing) {
  const Sheet report = perforated(Combine::mix, HoleFix::none, 8, 2);
  const Sheet none = perforated(Combine::mix, HoleFix::none, 0, 2);
  EXPECT_EQ(report.layout.elements.size(), none.layout.elements.size());
  EXPECT_GT(report.layout.violations.size(), 0u);
}

TEST(Perforation, MixMakesOneOpeningOfTheSummedAreaAndKeepCutsTheUnion) {
  const Sheet mix = perforated(Combine::mix, HoleFix::none, 0, 3);
  const Sheet keep = perforated(Combine::keep, HoleFix::none, 0, 3);
  const double one = Circle{0, 0, 16}.area();
  for (const Element& e : mix.layout.elements) {
    ASSERT_TRUE(e.circle);
    EXPECT_NEAR(e.area(), one * std::popcount(e.value), 1e-6) << e.id;  // all three overlap
  }
  bool merged = false;
  for (const Element& e : keep.layout.elements) {
    if (std::popcount(e.value) < 2) continue;
    ASSERT_TRUE(e.outline) << e.id;
    merged = true;
    EXPECT_LT(e.area(), one * std::popcount(e.value));  // the overlap counts once
    EXPECT_GT(e.area(), one * 1.2);
  }
  EXPECT_TRUE(merged);
  // Counts per value are the cells of each value, as in the report.
  const auto counts = value_counts(curdle(mix.design, 3, mix.design.field));
  for (uint32_t v = 0; v < 8; ++v) EXPECT_EQ(mix.layout.legend[v].count, counts[v]);
}

TEST(Perforation, OpenAreaAgreesWithThePixelsOfTheDrawing) {
  for (Combine combine : {Combine::mix, Combine::keep}) {
    Sheet s = perforated(combine, HoleFix::drop, 2, 4);
    s.layout.drawing.scale = 1, s.layout.drawing.dpi = 127;  // 5 px a millimetre
    const PreviewImage png = render_layout(s.layout);
    const Rgb metal{201, 205, 210};
    double open = 0;
    for (size_t p = 0; p < png.rgb.size(); p += 3) {
      // Antialiased edges count by how far they are from the metal towards the hole colour.
      const double d = std::abs(png.rgb[p] - metal.r) + std::abs(png.rgb[p + 1] - metal.g) +
                       std::abs(png.rgb[p + 2] - metal.b);
      open += d > 0 ? 1 : 0;
    }
    const double pixels = static_cast<double>(png.width) * png.height;
    EXPECT_NEAR(open / pixels, s.layout.open_area, 0.004) << static_cast<int>(combine);
  }
}

}  // namespace curdle

#include "kinds/park.h"

namespace curdle {
namespace {

// The paper's park (fig. 5): trees, benches and grey paving on 3 x 3 m cells, 300 mm clear.
LayoutSpec trees_and_benches() {
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("park"));
  spec.module_w = spec.module_h = 3000;
  spec.own<ParkKeys>().clearance = 300;
  spec.own<ParkKeys>().elements = {{"tree", false, true, 1000, 1000, Rgb{58, 138, 79}},
                                   {"bench", false, false, 1000, 450, Rgb{138, 90, 43}},
                                   {"grey paving", true, false, 0, 0, Rgb{154, 154, 154}}};
  return spec;
}

}  // namespace

// A park on a site with a sloping edge: its surfaces cover exactly the outline (cut along it),
// and every object stands whole inside it; those that would not are left out and counted.
TEST(Park, AnOutlineIsCoveredAndObjectsStandWholeInsideIt) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  LayoutSpec spec = trees_and_benches();
  // 48 x 48 m less a sloping cut across one corner and a step along x and y.
  const Polygon site = {{0, 0},         {30000, 0},     {48000, 20000}, {48000, 48000},
                        {20000, 48000}, {20000, 40000}, {0, 40000}};
  spec.outline = site;
  spec.size = std::array<double, 2>{48000, 48000};
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const Layout layout = lay_floor(d, spec, seed);
    double surfaces = 0;
    size_t shaped = 0;
    for (const Element& e : layout.elements) {
      if (e.type == "grey paving" || e.type == "white paving") {
        surfaces += e.area();
        shaped += e.outline.has_value();
        continue;
      }
      const Rect box = laid_bounds(e);
      for (const auto& corner : {std::array<double, 2>{box.x, box.y},
                                 {box.right(), box.y},
                                 {box.right(), box.top()},
                                 {box.x, box.top()}})
        EXPECT_TRUE(contains(site, corner[0], corner[1])) << e.id << " stands beyond the site";
    }
    EXPECT_NEAR(surfaces, polygon_area(site), 1e-2) << "seed " << seed;
    EXPECT_GT(shaped, 3u) << "surfaces along the sloping edge are cut to shape";
    std::ostringstream svg;
    write_layout_svg(svg, layout);
    EXPECT_NE(svg.str().find("id=\"outline\""), std::string::npos);
  }
}

TEST(Park, ElementsShareCellsWithoutOverlapAndSurfacesCoverTheArea) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  LayoutSpec spec = trees_and_benches();
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const CurdField f = curdle(d, seed, d.field);
    const Layout layout = make_layout(d, f, d.field, spec);
    std::map<std::pair<int64_t, int64_t>, std::vector<const Element*>> cells;
    std::map<std::string, uint64_t> per_type;
    double surfaces = 0;
    for (const Element& e : layout.elements) {
      cells[{e.row, e.column}].push_back(&e);
      ++per_type[e.type];
      if (e.type == "grey paving" || e.type == "white paving") surfaces += e.area();
    }
    EXPECT_NEAR(surfaces, layout.width * layout.height, 1e-3);  // surfaces tile the whole park
    const auto counts = value_counts(f);
    uint64_t trees = 0, benches = 0;
    for (uint32_t v = 0; v < 8; ++v)
      trees += (v & 1) ? counts[v] : 0, benches += (v & 2) ? counts[v] : 0;
    EXPECT_EQ(per_type["tree"], trees);
    EXPECT_EQ(per_type["bench"], benches);
    for (const auto& [cell, list] : cells) {
      std::vector<Rect> boxes;  // objects' footprints, to check clearances
      for (const Element* e : list) {
        if (e->type != "tree" && e->type != "bench") continue;
        const Rect box = e->circle
                             ? Rect{e->circle->cx - e->circle->d / 2,
                                    e->circle->cy - e->circle->d / 2, e->circle->d, e->circle->d}
                             : e->shape[0];
        const Rect& n = e->nominal;  // at least the clearance inside the cell
        EXPECT_GE(box.x - n.x, 300 - 1e-9);
        EXPECT_GE(n.right() - box.right(), 300 - 1e-9);
        EXPECT_GE(box.y - n.y, 300 - 1e-9);
        EXPECT_GE(n.top() - box.top(), 300 - 1e-9);
        for (const Rect& other : boxes) {  // and the clearance apart
          const double gap = std::max({other.x - box.right(), box.x - other.right(),
                                       other.y - box.top(), box.y - other.top()});
          EXPECT_GE(gap, 300 - 1e-9) << e->id;
        }
        boxes.push_back(box);
      }
    }
    SvgSummary svg = parse_svg(svg_of(layout));
    EXPECT_TRUE(svg.ids.count("type-tree") && svg.ids.count("type-bench") &&
                svg.ids.count("type-grey-paving"));
  }
}

}  // namespace curdle

#include "kinds/rhythm.h"

namespace curdle {

TEST(Rhythm, FinWidthsFollowTheValuesCentredInTheirBays) {
  const Design d = test::design(4, 1, {{"3/4", "3/4", "2/3"}, {"1/2", "3/4", "3/4"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("rhythm"));
  spec.module_w = 600, spec.module_h = 4200;
  spec.own<RhythmKeys>().widths = {0, 100, 180, 300};
  const CurdField f = curdle(d, 64, d.field);
  const Layout layout = make_layout(d, f, d.field, spec);
  const auto counts = value_counts(f);
  EXPECT_EQ(layout.elements.size(), 64 - counts[0]);
  for (uint32_t v = 0; v < 4; ++v) EXPECT_EQ(layout.legend[v].count, counts[v]);
  for (const Element& e : layout.elements) {
    EXPECT_EQ(e.value, f.value_at({e.cell_x, 0, 0}));
    EXPECT_NEAR(e.shape[0].w, spec.own<RhythmKeys>().widths[e.value], 1e-9);
    EXPECT_NEAR(e.shape[0].x + e.shape[0].w / 2, e.cell_x * 600 + 300, 1e-9);
    EXPECT_NEAR(e.shape[0].h, 4200, 1e-9);
  }
  SvgSummary svg = parse_svg(svg_of(layout));
  for (uint32_t v = 0; v < 4; ++v)
    EXPECT_EQ(svg.counts[v], v ? counts[v] : 0u) << "fins of value " << v;
}

TEST(Blocks, PlanAndElevationShowTheFirstBlockSeen) {
  const Design d = test::design(2, 3, {{"7/8", "3/4", "3/4"}, {"3/4", "1/2", "3/4"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("blocks"));
  spec.module_w = spec.module_h = 6000, spec.own<BlocksKeys>().voxel_h = 3000;
  const CurdField f = curdle(d, 3, d.field);
  const Layout layout = make_layout(d, f, d.field, spec);
  const auto counts = value_counts(f);
  EXPECT_EQ(layout.elements.size(), 512 - counts[0]);
  std::map<std::pair<double, double>, uint32_t> shown;
  std::multiset<std::string> in_plan;  // every block named once, under its plan cell
  for (const Layout::ViewCell& v : layout.views) {
    shown[{v.rect.x, v.rect.y}] = v.value;
    if (v.plan) in_plan.insert(v.elements.begin(), v.elements.end());
  }
  std::multiset<std::string> ids;
  for (const Element& e : layout.elements) ids.insert(e.id);
  EXPECT_EQ(in_plan, ids);
  for (int64_t x = 0; x < 8; ++x) {
    for (int64_t y = 0; y < 8; ++y) {  // plan: the top-most block
      uint32_t top = 0;
      for (int64_t z = 0; z < 8; ++z)
        if (const uint32_t v = f.value_at({x, y, z})) top = v;
      const auto it = shown.find({x * 6000.0, y * 6000.0});
      EXPECT_EQ(it == shown.end() ? 0u : it->second, top) << x << "," << y;
    }
    for (int64_t z = 0; z < 8; ++z) {  // elevation: the first block from the front
      uint32_t first = 0;
      for (int64_t y = 7; y >= 0; --y)
        if (const uint32_t v = f.value_at({x, y, z})) first = v;
      const auto it = shown.find({48000 + 12000 + x * 6000.0, z * 3000.0});
      EXPECT_EQ(it == shown.end() ? 0u : it->second, first) << x << "," << z;
    }
  }
  SvgSummary svg = parse_svg(svg_of(layout));
  for (uint32_t v = 1; v < 4; ++v)
    EXPECT_EQ(svg.counts[v], 0u);  // views are drawings, not elements
}

// Zones: no piece lies in an excluded zone and the areas still add up to the surface; every
// element whose laid centre a value zone holds takes its value, and the counts say so.
TEST(Layout, ZonesExcludeOrSetTheirValue) {
  const Design d = design(2, 2, {{"3/4", "3/4", "2/3", "2/3"}, {"1/2", "3/4", "3/4", "2/3"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("paving"));
  spec.module_w = 600, spec.module_h = 300, spec.joint = 5;
  spec.size = std::array<double, 2>{12000, 8000};
  spec.bond = 0.5;
  const Polygon planter = rect_polygon(Rect{7000, 3000, 2000, 3000});
  const Polygon plinth = {{1000, 5000}, {4000, 5000}, {4000, 6000},
                          {2000, 6000}, {2000, 7000}, {1000, 7000}};
  const Polygon band = rect_polygon(Rect{0, 0, 12000, 900});
  const Polygon corner = {{9500, 6500}, {11500, 6500}, {11500, 7800}};
  spec.zones = {{"planter", ZoneRule::exclude, 0, planter, *as_rectangles(planter)},
                {"plinth", ZoneRule::exclude, 0, plinth, *as_rectangles(plinth)},
                {"entrance", ZoneRule::value, 3, band, {}},
                {"corner", ZoneRule::value, 2, corner, {}}};
  const Layout layout = lay_floor(d, spec, 11);
  double elements = 0, openings = 0;
  std::map<std::string, std::vector<uint64_t>> held;
  for (const auto& z : spec.zones) held[z.name].assign(4, 0);
  for (const Element& e : layout.elements) {
    elements += e.area();
    for (const Rect& r : e.shape)
      for (const auto& z : spec.zones)
        for (const Rect& x : z.rects) EXPECT_NEAR(intersection(r, x), 0, 1e-6) << e.id << z.name;
    const Rect b = laid_bounds(e);
    const double cx = b.x + b.w / 2, cy = b.y + b.h / 2;
    if (contains(band, cx, cy)) {
      EXPECT_EQ(e.value, 3u) << e.id;
    } else if (contains(corner, cx, cy)) {
      EXPECT_EQ(e.value, 2u) << e.id;
    }
    for (const auto& z : spec.zones)
      if (contains(z.polygon, cx, cy)) ++held[z.name][e.value];
  }
  for (const Rect& o : layout.openings) openings += o.area();
  EXPECT_NEAR(openings, 6e6 + 4e6, 1e-3);
  EXPECT_NEAR(elements + joint_area(layout) + openings, 12000.0 * 8000.0, 1e-3);
  ASSERT_EQ(layout.zones.size(), 4u);
  for (const ZoneCount& z : layout.zones) EXPECT_EQ(z.by_value, held[z.name]) << z.name;
  EXPECT_GT(layout.zones[2].by_value[3], 30u);  // the band holds two courses' worth
  EXPECT_NEAR(layout.zones[1].area, 4e6, 1e-6);
  EXPECT_GT(layout.zones[0].cut, 0u);
}

// Rectilinear polygons become rectangles that cover exactly their area.
TEST(Geometry, RectilinearPolygonsBecomeRectangles) {
  const Polygon l = {{0, 0}, {3000, 0}, {3000, 1000}, {1000, 1000}, {1000, 2500}, {0, 2500}};
  const auto rects = as_rectangles(l);
  ASSERT_TRUE(rects);
  double area = 0;
  for (const Rect& r : *rects) area += r.area();
  EXPECT_NEAR(area, polygon_area(l), 1e-9);
  EXPECT_FALSE(as_rectangles({{0, 0}, {10, 0}, {10, 10}}));
  EXPECT_TRUE(is_simple(l));
  EXPECT_FALSE(is_simple({{0, 0}, {10, 10}, {10, 0}, {0, 10}}));  // a bow tie
  EXPECT_TRUE(contains(l, 500, 2000));
  EXPECT_FALSE(contains(l, 2000, 2000));
}

// A first-stage cell larger than a third of the floor's shorter side is warned of, with the
// bases and stage counts that fit; one that fits is not.
TEST(Layout, LargeFirstStageCellsAreWarnedOf) {
  auto notes_for = [](int base, int stages) {
    std::vector<std::string> probabilities(static_cast<size_t>(stages), "3/4");
    const Design d = design(base, 2, {probabilities});
    LayoutSpec spec = test::layout_spec();
    spec.set_kind(layout_kind("paving"));
    spec.module_w = 300, spec.module_h = 300;
    spec.size = std::array<double, 2>{9700, 4900};
    return lay_floor(d, spec, 2).notes;
  };
  const auto warned = notes_for(4, 3);  // first-stage cells 16 elements, 4.8 m, on a 4.9 m floor
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_NE(warned[0].find("4.80 x 4.80 m"), std::string::npos) << warned[0];
  EXPECT_NE(warned[0].find("base 2 and at most 3 stages"), std::string::npos) << warned[0];
  EXPECT_TRUE(notes_for(2, 3).empty());  // 4 elements, 1.2 m: fits
}

// layout.outline: no piece lies outside it, and the pieces, joints and excluded zones add up
// to the outline's area, for a centred, bonded grid as for a cornered stack.
TEST(Layout, AnOutlineIsCoveredExactly) {
  const Design d = design(2, 2, {{"3/4", "3/4", "2/3"}});
  const Polygon l = {{0, 0}, {12000, 0}, {12000, 5000}, {8000, 5000}, {8000, 8000}, {0, 8000}};
  for (const bool centred : {false, true}) {
    LayoutSpec spec = test::layout_spec();
    spec.set_kind(layout_kind("paving"));
    spec.module_w = 600, spec.module_h = 300, spec.joint = 5;
    spec.size = std::array<double, 2>{12000, 8000};
    spec.outline = l;
    spec.origin = centred ? Corner::bottom_left : Corner::top_right;
    spec.bond = centred ? 0.5 : 0;
    if (centred) spec.centred = true, spec.shift = {centring_shift(12000, 600, 5), 0};
    const Polygon planter = rect_polygon(Rect{3000, 3500, 2000, 3000});
    spec.zones = {{"planter", ZoneRule::exclude, 0, planter, *as_rectangles(planter)}};
    const Layout layout = lay_floor(d, spec, 5);
    ASSERT_FALSE(layout.outside.empty());
    double elements = 0;
    for (const Element& e : layout.elements) {
      elements += e.area();
      for (const Rect& r : e.shape) {
        for (const Rect& o : layout.outside) EXPECT_NEAR(intersection(r, o), 0, 1e-6) << e.id;
        EXPECT_TRUE(contains(l, r.x + r.w / 2, r.y + r.h / 2)) << e.id;
      }
    }
    EXPECT_NEAR(elements + joint_area(layout) + 6e6, polygon_area(l), 1e-3) << centred;
    std::ostringstream svg;
    write_layout_svg(svg, layout);
    EXPECT_NE(svg.str().find("id=\"outline\""), std::string::npos);
  }
}

// Sloping and curved edges: a terrace with a chamfered corner and an arched edge (a polyline),
// and a round tree pit kept free. No piece reaches beyond the outline or into the pit, pieces
// crossing them are cut to their exact shapes, and pieces, joints and the pit add up to the
// outline's area, stacked and in running bond.
TEST(Layout, SlopingAndCurvedEdgesCutPiecesExactly) {
  const Design d = design(3, 2, {{"3/4", "1/2"}});
  Polygon terrace = {{0, 0}, {8500, 0}, {10000, 1500}, {10000, 5000}};
  for (int i = 1; i < 24; ++i) {  // the arc through (5000, 6000), radius 13 m
    const double a0 = std::atan2(5000 + 7000.0, 5000.0), a1 = std::atan2(12000.0, -5000.0);
    const double a = a0 + (a1 - a0) * i / 24;
    terrace.push_back({5000 + 13000 * std::cos(a), -7000 + 13000 * std::sin(a)});
  }
  terrace.push_back({0, 5000});
  Polygon pit;
  for (int i = 0; i < 32; ++i)
    pit.push_back({3000 + 700 * std::cos(i * M_PI / 16), 2500 + 700 * std::sin(i * M_PI / 16)});
  auto on_edge = [](const Polygon& p, const std::array<double, 2>& v) {  // to a rounding error
    for (size_t i = 0; i < p.size(); ++i) {
      const auto& a = p[i];
      const auto& b = p[(i + 1) % p.size()];
      const double dx = b[0] - a[0], dy = b[1] - a[1];
      const double t =
          std::clamp(((v[0] - a[0]) * dx + (v[1] - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      if (std::hypot(a[0] + t * dx - v[0], a[1] + t * dy - v[1]) < 1e-6) return true;
    }
    return false;
  };
  auto on_or_inside = [&](const Polygon& p, const std::array<double, 2>& v) {
    return contains(p, v[0], v[1]) || on_edge(p, v);
  };
  auto strictly_inside = [&](const Polygon& p, const std::array<double, 2>& v) {
    return contains(p, v[0], v[1]) && !on_edge(p, v);
  };
  for (const double bond : {0.0, 0.5}) {
    LayoutSpec spec = test::layout_spec();
    spec.set_kind(layout_kind("paving"));
    spec.module_w = 500, spec.module_h = 250, spec.joint = 6;
    spec.size = std::array<double, 2>{10000, 6000};
    spec.outline = terrace;
    spec.bond = bond;
    spec.zones = {{"tree pit", ZoneRule::exclude, 0, pit, {}}};
    const Layout layout = lay_floor(d, spec, 5);
    ASSERT_FALSE(layout.cut_away.empty());
    double elements = 0;
    size_t shaped = 0;
    for (const Element& e : layout.elements) {
      elements += e.area();
      std::vector<std::array<double, 2>> corners;
      if (e.outline) {
        ++shaped;
        EXPECT_TRUE(e.cut) << e.id;
        for (const Ring& ring : e.outline->rings)
          corners.insert(corners.end(), ring.begin(), ring.end());
      }
      for (const Rect& r : e.shape)
        corners.insert(corners.end(),
                       {{r.x, r.y}, {r.right(), r.y}, {r.right(), r.top()}, {r.x, r.top()}});
      for (const auto& v : corners) {
        EXPECT_TRUE(on_or_inside(terrace, v)) << e.id << " has a corner beyond the outline";
        EXPECT_FALSE(strictly_inside(pit, v)) << e.id << " has a corner in the pit";
      }
    }
    EXPECT_GT(shaped, 40u) << "pieces along the arc, the chamfer and the pit are cut to shape";
    EXPECT_NEAR(elements + joint_area(layout) + polygon_area(pit), polygon_area(terrace), 1e-2)
        << "bond " << bond;
  }
}

}  // namespace curdle
