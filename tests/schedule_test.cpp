// Schedules: strict CSV, quantities add up to the schedule, counts per value match the report.
#include "export/schedules/schedule.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "building_support.h"
#include "curdle/curdling.h"
#include "curdle/overlay.h"
#include "export_support.h"
#include "layout/builder.h"
#include "test_support.h"

namespace curdle {
namespace {}  // namespace

TEST(Schedule, QuantitiesAddUpAndCountsMatchTheReport) {
  Design d = test::design(4, 2, {{"3/4", "1/2", "1/2"}, {"1/2", "1/2", "1/2"}});
  d.curds[0].name = "grey, light";  // a comma, to be quoted
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("paving"));
  spec.module_w = spec.module_h = 400, spec.joint = 5;
  spec.size = std::array<double, 2>{12000, 8100};  // cut edge tiles
  spec.value_colours = {Rgb{200, 200, 200}, Rgb{100, 100, 100}, Rgb{40, 40, 40}, Rgb{40, 40, 40}};
  spec.ordering.spare = 0.05, spec.ordering.pack = 20, spec.ordering.lot_rows = 5;
  const auto cells = elements_to_cover(spec);
  d.field.size = {cells[0], cells[1], 1};
  const CurdField f = curdle(d, 4, d.field);
  const Layout layout = make_layout(d, f, d.field, spec);

  std::ostringstream schedule, quantities;
  write_schedule_csv(schedule, layout);
  write_quantities_csv(quantities, layout);
  // Spreadsheets need the UTF-8 byte-order mark; after it, strict RFC 4180.
  const std::string mark = "\xEF\xBB\xBF";
  ASSERT_EQ(schedule.str().substr(0, 3), mark);
  ASSERT_EQ(quantities.str().substr(0, 3), mark);
  const auto rows = strict_csv(schedule.str().substr(3));
  ASSERT_EQ(rows.size(), layout.elements.size() + 1);
  auto column = [&](const std::vector<std::vector<std::string>>& table, const std::string& name) {
    const auto& h = table[0];
    const auto it = std::find(h.begin(), h.end(), name);
    EXPECT_NE(it, h.end()) << name;
    return static_cast<size_t>(it - h.begin());
  };
  EXPECT_EQ(rows[0][column(rows, "value") + 1], "grey, light");
  const size_t value = column(rows, "value"), cut_column = column(rows, "cut"),
               lot_column = column(rows, "lot"), row_column = column(rows, "row"),
               area_column = column(rows, "area_m2");
  double schedule_area = 0;
  std::map<int, uint64_t> per_value;
  int64_t cut = 0, last_lot = 0;
  double area = 0;
  for (size_t r = 1; r < rows.size(); ++r) {
    ++per_value[std::stoi(rows[r][value])];
    cut += rows[r][cut_column] == "1";
    schedule_area += std::stod(rows[r][area_column]);
    const int64_t lot = std::stoll(rows[r][lot_column]);
    EXPECT_EQ(lot, std::stoll(rows[r][row_column]) / 5 + 1);  // five rows a lot
    EXPECT_GE(lot, last_lot);                                 // lots follow the laying order
    last_lot = lot;
  }
  for (const Element& e : layout.elements) area += e.area();
  const auto counts = value_counts(f);
  for (int v = 0; v < 4; ++v) EXPECT_EQ(per_value[v], counts[v]) << "value " << v;
  EXPECT_GT(cut, 0);

  const auto q = strict_csv(quantities.str().substr(3));
  ASSERT_EQ(q.size(), 5u);  // one line per value: values 2 and 3 share a colour, not a name
  uint64_t ordered = 0;
  double ordered_area = 0;
  for (size_t r = 1; r < q.size(); ++r) {
    const uint64_t count = std::stoull(q[r][column(q, "count")]);
    EXPECT_EQ(count, std::stoull(q[r][column(q, "whole")]) + std::stoull(q[r][column(q, "cut")]));
    ordered += count;
    ordered_area += std::stod(q[r][column(q, "laid_area_m2")]);
    // Every piece, cut or whole, is bought as a 400 x 400 slab.
    EXPECT_NEAR(std::stod(q[r][column(q, "stock_area_m2")]), count * 0.16, 1e-6);
    EXPECT_EQ(q[r][column(q, "size_mm")], "400 x 400");
    const uint64_t with_spare = std::stoull(q[r][column(q, "count_with_spare")]);
    EXPECT_EQ(with_spare, static_cast<uint64_t>(std::ceil(count * 1.05 - 1e-9)));
    EXPECT_EQ(std::stoull(q[r][column(q, "packs")]), (with_spare + 19) / 20);
    EXPECT_NEAR(std::stod(q[r][column(q, "area_to_buy_m2")]), with_spare * 0.16, 1e-6);
  }
  EXPECT_EQ(ordered, layout.elements.size());
  EXPECT_NEAR(ordered_area, area / 1e6, 1e-5);
  EXPECT_NEAR(schedule_area, area / 1e6, 1e-5);  // the pieces' own areas add up
}

}  // namespace curdle

#include <regex>

#include "export/drawing/install.h"

namespace curdle {

// A name that begins like a formula is text in every CSV file (OWASP's rule): a spreadsheet
// shows =HYPERLINK(...) instead of running it.
TEST(Schedule, NamesThatLookLikeFormulasStayText) {
  Design d = test::design(2, 2, {{"3/4", "2/3"}});
  d.curds[0].name = "-dark";
  LayoutSpec spec = test::layout_spec("paving");
  spec.size = std::array<double, 2>{900, 600};
  spec.materials = {"=HYPERLINK(\"http://x\",\"y\")", "@SUM(A1)"};
  const auto cells = elements_to_cover(spec);
  d.field.size = {cells[0], cells[1], 1};
  const Layout layout = make_layout(d, curdle(d, 2, d.field), d.field, spec);
  std::ostringstream schedule, quantities, lots;
  write_schedule_csv(schedule, layout);
  write_quantities_csv(quantities, layout);
  write_lots_csv(lots, layout);
  for (const std::string& csv : {schedule.str(), quantities.str(), lots.str()}) {
    for (const char* formula : {",=", ",@", ",-dark", ",\"=", ",\"@"})
      EXPECT_EQ(csv.find(formula), std::string::npos) << formula << " in\n" << csv.substr(0, 300);
    EXPECT_NE(csv.find("'=HYPERLINK"), std::string::npos);
  }
  EXPECT_NE(schedule.str().find(",'-dark"), std::string::npos);  // the curd's column
}

TEST(Install, TheMapNamesEveryElementAndWhereLayingStarts) {
  Design d = test::design(4, 2, {{"3/4", "1/2"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("facade"));
  spec.module_w = 600, spec.module_h = 300, spec.joint = 10;
  spec.size = std::array<double, 2>{6000, 3000};
  spec.origin = Corner::top_right;
  spec.own<FacadeKeys>().openings = {{1000, 0, 1200, 2100}};
  const auto cells = elements_to_cover(spec);
  d.field.size = {cells[0], cells[1], 1};
  const Layout layout = make_layout(d, curdle(d, 6, d.field), d.field, spec);
  std::ostringstream out;
  write_install_svg(out, layout, plan_installer_sheets(layout));
  const std::string svg = out.str();
  std::set<std::string> labelled, ids;
  const std::regex label("<g id=\"(F-R[0-9]+-C[0-9]+)\" class=\"element\"");
  for (std::sregex_iterator it(svg.begin(), svg.end(), label), end; it != end; ++it)
    labelled.insert((*it)[1]);
  for (const Element& e : layout.elements) ids.insert(e.id);
  EXPECT_EQ(labelled, ids);
  EXPECT_NE(svg.find("id=\"laying-order\""), std::string::npos);
  EXPECT_NE(svg.find(">R0<"), std::string::npos);
}

}  // namespace curdle

#include <fmt/format.h>

#include "layout/piece.h"
#include "layout/wkt.h"
#include "layout_support.h"

namespace curdle {

// Every row of schedule.csv carries its piece's shape, rectangles and circles too, so that a GIS
// reads each as a feature (QGIS showed 5 of 470 courtyard pieces: only the cut ones had one).
TEST(Schedule, EveryPieceHasItsShapeInWkt) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  LayoutSpec spec = test::trees_and_benches();
  spec.size = std::array<double, 2>{20000, 14500};  // cut edge cells
  const Layout layout = lay_floor(d, spec, 4);
  std::ostringstream out;
  write_schedule_csv(out, layout);
  const auto rows = strict_csv(out.str().substr(3));
  const auto& head = rows[0];
  const size_t wkt = std::find(head.begin(), head.end(), "shape_wkt") - head.begin();
  ASSERT_LT(wkt, head.size());
  ASSERT_EQ(rows.size(), layout.elements.size() + 1);
  size_t circles = 0, rectangles = 0;
  for (size_t i = 0; i < layout.elements.size(); ++i) {
    const Element& e = layout.elements[i];
    const std::string& shape = rows[i + 1][wkt];
    EXPECT_TRUE(shape.starts_with("POLYGON ((") || shape.starts_with("MULTIPOLYGON (((")) << e.id;
    if (e.circle) {
      ++circles;
      EXPECT_GT(std::count(shape.begin(), shape.end(), ','), 16) << e.id << ": " << shape;
    } else if (is_rectangle(e)) {
      ++rectangles;
      const Rect b = laid_bounds(e);
      const std::string x0 = mm_text(b.x), y0 = mm_text(b.y), x1 = mm_text(b.right()),
                        y1 = mm_text(b.top());
      EXPECT_EQ(shape, fmt::format("POLYGON (({0} {1}, {2} {1}, {2} {3}, {0} {3}, {0} {1}))", x0,
                                   y0, x1, y1))
          << e.id;
    }
  }
  EXPECT_GT(circles, 0u);
  EXPECT_GT(rectangles, 0u);
}

// A one-brick wall counted whole: its face's stretchers, headers through the wall and queen
// closers each on a line of their own, and a backing brick behind every face brick that does
// not run through. The hand count for a one-brick wall of 215 x 102.5 x 65 bricks with 10 mm
// joints, English or Flemish bond alike: each metre of a course holds 1000 / 112.5 = 8.889
// brick-lengths across the wall's thickness (a stretcher and its backing per 225 mm, or a
// header per 112.5 mm), and a metre of height 1000 / 75 = 13.333 courses: 118.5 bricks a m².
// The pavilion's 451.2 m² of face, its corners and all, lies within 1 % of it.
TEST(Schedule, AOneBrickWallIsCountedWholeWithEachPartOnItsOwnLine) {
  constexpr double kHandCount = 1000.0 / 112.5 * 1000.0 / 75;  // 118.52 a m²
  for (const char* bond : {"english", "flemish"}) {
    const Layout l = test::lay_recipe(
        test::pavilion_recipe("wall = \"one-brick\"\nbacking = \"Class B engineering brick\"\n",
                              fmt::format("bond = \"{}\"\nunit = \"brick\"\n", bond)));
    std::ostringstream out;
    write_quantities_csv(out, l);
    const auto rows = strict_csv(out.str().substr(3));
    std::map<std::string, uint64_t> by_type;
    uint64_t total = 0;
    for (size_t i = 1; i < rows.size(); ++i) {
      by_type[rows[i][0]] += std::stoull(rows[i][5]);
      total += std::stoull(rows[i][5]);
      if (rows[i][0] == "brick, backing") {
        EXPECT_EQ(rows[i][1], "Class B engineering brick");
      }
    }
    const double per_m2 = static_cast<double>(total) / (64.0 * 7.05);
    EXPECT_NEAR(per_m2 / kHandCount, 1, 0.01) << bond << ": " << per_m2 << " a m²";
    for (const char* line : {"brick", "brick, header", "brick, queen closer", "brick, backing"})
      EXPECT_GT(by_type[line], 100u) << bond << ": " << line;
    EXPECT_EQ(by_type.count("brick, snap header (a half)"), 0u);
  }
  // A half-brick leaf in English bond: its headers are snap headers, as deep as the leaf, and
  // nothing stands behind it.
  const Layout leaf =
      test::lay_recipe(test::pavilion_recipe("", "bond = \"english\"\nunit = \"brick\"\n"));
  std::ostringstream out;
  write_quantities_csv(out, leaf);
  EXPECT_NE(out.str().find("brick, snap header (a half)"), std::string::npos);
  EXPECT_EQ(out.str().find("backing"), std::string::npos);
  for (const Element& e : leaf.elements) EXPECT_EQ(e.depth, 0) << e.id;
}

// A special (a brick for a 135° corner) is made to order and bought by the piece, while the
// rest come in packs of 500.
TEST(Schedule, SpecialsAreBoughtByThePiece) {
  const Layout l = test::lay_recipe(test::building_recipe(
      "panel = [215, 65]\njoint = 10\nunit = \"brick\"\npack = 500\n",
      "plan = [[0, 0], [9000, 0], [12000, 3000], [12000, 8000], [0, 8000]]\nheight = 750\n"));
  std::ostringstream out;
  write_quantities_csv(out, l);
  const auto rows = strict_csv(out.str().substr(3));
  size_t specials = 0;
  for (size_t i = 1; i < rows.size(); ++i) {
    const bool special = rows[i][0].find("special for a 135.0° outer corner") != std::string::npos;
    specials += special;
    EXPECT_EQ(rows[i][13], special ? "1" : "500") << rows[i][0];
    if (special) {
      EXPECT_EQ(rows[i][14], rows[i][11]) << "as many as are laid";
    }
  }
  EXPECT_GT(specials, 0u);
}

}  // namespace curdle
