// Tests of builder.h.
#include "layout/builder.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "layout/joint_area.h"
#include "layout_support.h"

namespace curdle {
using test::design;

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
    // A value zone holds the pieces whose centre it holds; an excluded zone none: a piece cut
    // along it keeps its parts outside it, whatever its bounds' centre.
    for (const auto& z : spec.zones)
      if (z.rule == ZoneRule::value && contains(z.polygon, cx, cy)) ++held[z.name][e.value];
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

// A drain 100 mm wide through the middle of a column of 600 mm slabs cuts each in two, parts
// either side: the drain holds none of them (it was said to hold them all), and they are its cut.
TEST(Layout, ADrainThroughSlabsHoldsNoneOfThem) {
  const Design d = design(2, 2, {{"3/4", "3/4", "2/3", "2/3"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("paving"));
  spec.module_w = 600, spec.module_h = 300, spec.joint = 5;
  spec.size = std::array<double, 2>{6000, 3000};
  const Polygon drain = rect_polygon(Rect{3025 + 250, 0, 100, 3000});  // mid-slab, column 5
  spec.zones = {{"drain", ZoneRule::exclude, 0, drain, *as_rectangles(drain)}};
  const Layout layout = lay_floor(d, spec, 3);
  ASSERT_EQ(layout.zones.size(), 1u);
  uint64_t held = 0;
  for (const uint64_t n : layout.zones[0].by_value) held += n;
  EXPECT_EQ(held, 0u);
  EXPECT_EQ(layout.zones[0].cut, 10u);  // the column's ten courses
}

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
      // A piece says it was cut to a polygon by its form, not by its layout's kind.
      EXPECT_EQ(e.form == ElementForm::cut_piece, e.outline.has_value()) << e.id;
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

// A site's pieces are cut along its edges on as many threads as the run has, and what lies
// beyond its outline beside them: the same pieces and the same cut-away, to the bit and in the
// same order, on one thread as on four.
TEST(Layout, PiecesCutOnManyThreadsAreThoseCutOnOne) {
  const Design d = design(3, 2, {{"3/4", "1/2"}});
  Polygon site;
  for (int i = 0; i < 90; ++i)  // a wavy edge: most pieces along it are cut to shape
    site.push_back({5000 + 4800 * std::cos(i * M_PI / 45) + 150 * std::sin(i * 0.9),
                    3000 + 2800 * std::sin(i * M_PI / 45)});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("paving"));
  spec.module_w = 300, spec.module_h = 300, spec.joint = 5;
  spec.size = std::array<double, 2>{10000, 6000};
  spec.outline = site;
  auto lay_on = [&](int threads) {
    Layout out;
    tbb::task_arena(threads).execute([&] { out = lay_floor(d, spec, 5); });
    return out;
  };
  const Layout one = lay_on(1), many = lay_on(4);
  ASSERT_EQ(one.elements.size(), many.elements.size());
  EXPECT_EQ(one.omitted, many.omitted);
  ASSERT_EQ(one.cut_away.size(), many.cut_away.size());  // made beside the pieces
  ASSERT_FALSE(one.cut_away.empty());
  for (size_t i = 0; i < one.cut_away.size(); ++i)
    EXPECT_EQ(one.cut_away[i].rings, many.cut_away[i].rings);
  size_t shaped = 0;
  for (size_t i = 0; i < one.elements.size(); ++i) {
    const Element &a = one.elements[i], &b = many.elements[i];
    ASSERT_EQ(a.id, b.id);
    EXPECT_EQ(a.cut, b.cut) << a.id;
    EXPECT_EQ(a.shape, b.shape) << a.id;
    ASSERT_EQ(a.outline.has_value(), b.outline.has_value()) << a.id;
    if (a.outline) {
      ++shaped;
      EXPECT_EQ(a.outline->rings, b.outline->rings) << a.id;
      EXPECT_EQ(a.outline->area, b.outline->area) << a.id;
    }
  }
  EXPECT_GT(shaped, 100u);
}

}  // namespace curdle

namespace curdle {

// Cutting tests every element against every corner of a sloping edge: a surface of 90,000
// elements along a 4,000-corner circle is refused before anything is laid, with the figure.
TEST(Layout, CuttingWorkIsBoundedBeforeLaying) {
  const Design d = test::design(2, 2, {{"3/4"}});
  LayoutSpec spec = test::layout_spec("paving");
  spec.size = std::array<double, 2>{90000, 90000};
  for (int i = 0; i < 4000; ++i) {
    const double a = 2 * 3.14159265358979 * i / 4000;
    spec.outline.push_back({45000 + 44000 * std::cos(a), 45000 + 44000 * std::sin(a)});
  }
  try {
    lay_floor(d, spec, 1);
    FAIL() << "90,000 elements along 4,000 corners were cut";
  } catch (const ResourceLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("90000 elements along 4000 corners"), std::string::npos)
        << e.what();
  }
}

}  // namespace curdle
