// The drawing set: installer's sheets where every ID reads (at least 2 mm high), inside its
// piece or beside it on the same sheet, and no two labels overlap; layout.pdf has sheet 1 and
// one page per installer's sheet on ISO paper; layout.png is sheet 1 with the layout's pixels.
#include "layout/installer_sheets.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "curdle/error.h"
#include "export/drawing/drawing_set.h"
#include "export/drawing/layout_png.h"
#include "layout/builder.h"
#include "pattern_support.h"

namespace curdle {
namespace {

using test::pattern_layout;

bool within(const Rect& outer, const Rect& inner) {
  const double e = 1e-6;
  return inner.x >= outer.x - e && inner.y >= outer.y - e && inner.right() <= outer.right() + e &&
         inner.top() <= outer.top() + e;
}

// How wide cairo sets the text with the font and size the sheets use, mm.
double set_width(const std::string& text, double cap_height) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
  cairo_t* cr = cairo_create(s);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, cap_height / kCapHeightEm);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_destroy(cr);
  cairo_surface_destroy(s);
  return e.x_advance;
}

// A segment runs through the inside of a box: sampled finely, as the test's own measure.
bool runs_through(std::array<double, 2> a, std::array<double, 2> b, const Rect& r) {
  const Rect inner{r.x + 1e-3, r.y + 1e-3, r.w - 2e-3, r.h - 2e-3};
  for (int k = 0; k <= 2000; ++k) {
    const double t = k / 2000.0;
    const double x = a[0] + (b[0] - a[0]) * t, y = a[1] + (b[1] - a[1]) * t;
    if (x > inner.x && x < inner.right() && y > inner.y && y < inner.top()) return true;
  }
  return false;
}

double cross(std::array<double, 2> o, std::array<double, 2> a, std::array<double, 2> b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Leaders that cross another label, a reserved box or another leader, where neither is a
// crowded label's (the plan's last resort, counted in over_labels).
size_t leaders_crossing(const InstallerPlan& plan, const std::vector<Rect>& reserved) {
  size_t crossing = 0;
  for (size_t i = 0; i < plan.labels.size(); ++i) {
    const InstallerLabel& l = plan.labels[i];
    if (l.inside || l.crowded) continue;
    const auto a = l.anchor, b = leader_end(l);
    const Rect reach{std::min(a[0], b[0]), std::min(a[1], b[1]), std::fabs(b[0] - a[0]),
                     std::fabs(b[1] - a[1])};
    auto near = [&](const Rect& r) {
      return r.x <= reach.right() && reach.x <= r.right() && r.y <= reach.top() &&
             reach.y <= r.top();
    };
    for (size_t j = 0; j < plan.labels.size(); ++j) {
      const InstallerLabel& m = plan.labels[j];
      if (j == i || !near(m.box)) continue;
      if (!m.crowded && runs_through(a, b, m.box) && ++crossing <= 5)
        ADD_FAILURE() << "the leader of " << l.text << " crosses the label " << m.text;
      if (m.inside || m.crowded) continue;
      const auto c = m.anchor, d = leader_end(m);
      if (cross(a, b, c) * cross(a, b, d) < 0 && cross(c, d, a) * cross(c, d, b) < 0 &&
          ++crossing <= 5)
        ADD_FAILURE() << "the leader of " << l.text << " crosses that of " << m.text;
    }
    for (const Rect& r : reserved)
      if (near(r) && runs_through(a, b, r) && ++crossing <= 5)
        ADD_FAILURE() << "the leader of " << l.text << " crosses a caption or the start corner";
  }
  return crossing;
}

class InstallerSheets : public ::testing::TestWithParam<const char*> {};

TEST_P(InstallerSheets, EveryIdReadsAndNoTwoLabelsOverlap) {
  Layout layout = pattern_layout(GetParam());
  layout.drawing.installer_set = InstallerSet::labelled;  // bricks and small tiles too
  const InstallerPlan plan = plan_installer_sheets(layout);
  const std::vector<InstallerPiece> pieces = installer_pieces(layout);
  ASSERT_EQ(plan.labels.size(), pieces.size());
  EXPECT_EQ(plan.unplaced, 0u);
  EXPECT_GE(plan.text_mm, 2.0);
  EXPECT_NE(std::find(standard_scales().begin(), standard_scales().end(), plan.scale),
            standard_scales().end());
  EXPECT_EQ(plan.sheets.size(), plan.grid_columns * plan.grid_rows);
  size_t inside = 0;
  for (size_t i = 0; i < pieces.size(); ++i) {
    const InstallerLabel& l = plan.labels[i];
    EXPECT_EQ(l.text, pieces[i].id);
    const Rect& window = plan.sheets.at(l.sheet).window;
    EXPECT_TRUE(within(window, l.box)) << l.text << " leaves its sheet";
    EXPECT_TRUE(l.anchor[0] >= window.x && l.anchor[0] <= window.right() &&
                l.anchor[1] >= window.y && l.anchor[1] <= window.top())
        << l.text << " is labelled on another sheet than its centre's";
    if (l.inside) {
      ++inside;
      EXPECT_TRUE(std::any_of(pieces[i].parts.begin(), pieces[i].parts.end(),
                              [&](const Rect& part) { return within(part, l.box); }))
          << l.text << " is said to be inside its piece but is not";
    }
    // The text as set fits the box the plan kept for it (on paper, mm), in one line or two.
    const double room = (l.rotated ? l.box.h : l.box.w) / plan.scale;
    const double depth = (l.rotated ? l.box.w : l.box.h) / plan.scale;
    const std::vector<std::string> lines = label_lines(l);
    std::string joined;
    for (const std::string& line : lines) {
      EXPECT_LE(set_width(line, plan.text_mm), room) << l.text;
      joined += (joined.empty() ? "" : "-") + line;
    }
    EXPECT_EQ(joined, l.text);
    EXPECT_GE(depth + 1e-9, lines.size() * label_height_mm(plan.text_mm)) << l.text;
  }
  EXPECT_GT(inside, pieces.size() / 2) << "most pieces hold their own label";
  // No two label boxes overlap: sweep along x.
  std::vector<const InstallerLabel*> order;
  for (const InstallerLabel& l : plan.labels) order.push_back(&l);
  std::sort(order.begin(), order.end(),
            [](const InstallerLabel* a, const InstallerLabel* b) { return a->box.x < b->box.x; });
  size_t overlapping = 0;
  for (size_t i = 0; i < order.size(); ++i)
    for (size_t j = i + 1; j < order.size() && order[j]->box.x < order[i]->box.right(); ++j)
      if (overlaps(order[i]->box, order[j]->box)) {
        if (++overlapping <= 5) ADD_FAILURE() << order[i]->text << " overlaps " << order[j]->text;
      }
  EXPECT_EQ(overlapping, 0u);
  // Nor does any label lie on a match line's caption or the start corner.
  std::vector<Rect> reserved = plan.start_corner;
  for (const MatchCaption& c : plan.captions) {
    reserved.push_back(c.box);
    EXPECT_TRUE(within(plan.sheets.at(c.sheet).window, c.box)) << match_caption_text(c);
    EXPECT_LE(set_width(match_caption_text(c), kMatchCaptionMm),
              (c.vertical ? c.box.h : c.box.w) / plan.scale);
  }
  EXPECT_EQ(plan.start_corner.empty(), !layout.kind->laid_from_corner());
  size_t covered = 0;
  for (const InstallerLabel& l : plan.labels)
    for (const Rect& r : reserved)
      if (overlaps(l.box, r) && ++covered <= 5)
        ADD_FAILURE() << l.text << " lies on a caption or the start corner";
  EXPECT_EQ(covered, 0u);
  // No leader runs through another label, a caption or the start corner, or meets another
  // leader, but those of crowded labels, which are few; in a park (trees standing where their
  // cells put them, one may straddle a match line), under 1 %.
  EXPECT_EQ(leaders_crossing(plan, reserved), 0u);
  EXPECT_EQ(plan.over_labels,
            static_cast<size_t>(std::count_if(plan.labels.begin(), plan.labels.end(),
                                              [](const InstallerLabel& l) { return l.crowded; })));
  EXPECT_LE(plan.over_labels * 50, pieces.size()) << "more than 2 % of the leaders are crowded";
  if (layout.kind->name() == "park") {  // few pieces, room round them: under 1 %
    EXPECT_LE(plan.over_labels * 100, pieces.size());
  }
  for (size_t i = 0; i < pieces.size(); ++i)
    if (plan.labels[i].crowded)
      std::cerr << "  crowded: " << pieces[i].id << " " << pieces[i].bounds.w << " x "
                << pieces[i].bounds.h << " mm\n";
  std::cerr << GetParam() << ": 1 : " << plan.scale << ", " << plan.sheets.size() << " sheets, "
            << plan.over_labels << " of " << pieces.size() << " leaders crowded\n";
  if (plan.grid_columns * plan.grid_rows > 1) {
    EXPECT_FALSE(plan.captions.empty());
  }
  // Sheets meet at joints: no match line runs through a piece, so each holds its own label.
  // Under a bond no vertical joint runs straight up the wall: there a vertical edge may cut one
  // piece of each course, and no more. A park's trees and benches stand on its ground cells, so
  // no edge there runs along joints only.
  std::map<std::pair<size_t, int64_t>, size_t> split_per_course;  // (sheet, row) -> pieces
  size_t split = 0;
  const bool bonded = layout.bond > 0;
  for (size_t i = 0; i < pieces.size(); ++i) {
    const InstallerPiece& p = pieces[i];
    for (size_t k = 0; k < plan.sheets.size(); ++k) {
      const InstallerSheet& sheet = plan.sheets[k];
      const Rect& w = sheet.window;
      const bool across_x =
          p.bounds.x < w.x - 1e-6 && p.bounds.right() > w.x + 1e-6 && sheet.column > 0;
      const bool across_y = p.bounds.y < w.y - 1e-6 && p.bounds.top() > w.y + 1e-6 && sheet.row > 0;
      const bool by_x = across_x && p.bounds.y < w.top() && p.bounds.top() > w.y;
      const bool by_y = across_y && p.bounds.x < w.right() && p.bounds.right() > w.x;
      if (by_x && bonded && ++split_per_course[{k, layout.elements[i].row}] == 1) continue;
      if ((by_x || by_y) && layout.kind->name() != "park" && ++split <= 5)
        ADD_FAILURE() << p.id << " is split by the edge of sheet " << sheet.row << ","
                      << sheet.column;
    }
  }
  EXPECT_EQ(split, 0u);

  // layout.pdf: sheet 1 and one page per installer's sheet, each an ISO sheet.
  std::ostringstream pdf;
  write_layout_pdf(pdf, layout, plan);
  const std::string bytes = pdf.str();
  ASSERT_EQ(bytes.rfind("%PDF-", 0), 0u);
  size_t pages = 0;
  // cairo writes each page's dictionary as "/Type /Page % N".
  for (size_t at = 0; (at = bytes.find("/Type /Page %", at)) != std::string::npos; ++at) ++pages;
  EXPECT_EQ(pages, 1 + plan.sheets.size());
}

INSTANTIATE_TEST_SUITE_P(
    Patterns, InstallerSheets,
    ::testing::Values("brick-facade-five-storeys.toml", "plaza-three-colours.toml",
                      "perforated-aluminium-screen.toml", "paper/fig8-segment-of-large-curd.toml",
                      "brick-facade-stretcher-bond.toml", "courtyard-l-shaped.toml",
                      "paper/fig5a-park.toml", "../examples/briefs/cafe-park.toml"));

// Small units are drawn as a coursed set: no labels, 1 : 20 unless named, landscape, and every
// piece's centre on exactly one sheet.
TEST(InstallerSheets, SmallUnitsMakeACoursedSetAtOneToTwenty) {
  Layout layout = pattern_layout("brick-facade-stretcher-bond.toml");  // 215 x 65 mm bricks
  const InstallerPlan plan = plan_installer_sheets(layout);
  EXPECT_TRUE(plan.coursed);
  EXPECT_TRUE(plan.labels.empty());
  EXPECT_EQ(plan.scale, 20);
  EXPECT_EQ(plan.paper.name, "A3");
  EXPECT_TRUE(plan.landscape);
  EXPECT_LE(plan.sheets.size(), 6u);  // a 9 x 6 m wall: was 30 labelled sheets at 1 : 5
  for (const InstallerPiece& p : plan.pieces) {
    const double cx = p.bounds.x + p.bounds.w / 2, cy = p.bounds.y + p.bounds.h / 2;
    const auto holding = std::count_if(plan.sheets.begin(), plan.sheets.end(), [&](const auto& s) {
      return cx >= s.window.x && cx < s.window.right() && cy >= s.window.y && cy < s.window.top();
    });
    EXPECT_EQ(holding, 1) << p.id;
  }
  std::ostringstream pdf;
  write_layout_pdf(pdf, layout, plan);
  EXPECT_EQ(pdf.str().rfind("%PDF-", 0), 0u);

  // The recipe names the scale and paper; a labelled set is asked for by name.
  layout.drawing.installer_scale = 50;
  layout.drawing.installer_paper = "A2";
  const InstallerPlan named = plan_installer_sheets(layout);
  EXPECT_EQ(named.scale, 50);
  EXPECT_EQ(named.paper.name, "A2");
  EXPECT_EQ(named.sheets.size(), 1u);
  layout.drawing = {};
  layout.drawing.installer_set = InstallerSet::labelled;
  const InstallerPlan labelled = plan_installer_sheets(layout);
  EXPECT_FALSE(labelled.coursed);
  EXPECT_EQ(labelled.labels.size(), labelled.pieces.size());
  // Large panels stay labelled when left automatic.
  EXPECT_FALSE(plan_installer_sheets(pattern_layout("brick-facade-five-storeys.toml")).coursed);
}

TEST(LayoutSheet, IsSheetOneWithTheLayoutsOwnPixels) {
  Layout layout = pattern_layout("brick-facade-five-storeys.toml");
  layout.drawing.dpi = 50;  // small and quick
  const OverviewSheet sheet = overview_sheet(layout);
  EXPECT_EQ(sheet.paper.name, "A3");
  const PreviewImage png = render_layout_sheet(layout, plan_installer_sheets(layout));
  // layout.png, encoded as its rows are read off the sheet, holds these very pixels.
  EXPECT_EQ(layout_sheet_png(layout, plan_installer_sheets(layout)), encode_png(png, 50));
  EXPECT_EQ(png.width, static_cast<int>(std::lround(420 * 50 / 25.4)));
  EXPECT_EQ(png.height, static_cast<int>(std::lround(297 * 50 / 25.4)));
  // Every pixel of the layout's own picture is somewhere on the sheet, unchanged: find its
  // first row by its left-most pixels.
  const PreviewImage own = render_layout(layout);
  bool found = false;
  for (int y = 0; y + own.height <= png.height && !found; ++y)
    for (int x = 0; x + own.width <= png.width && !found; ++x) {
      bool same = true;
      // Inside its outline, which is drawn over its edge.
      for (int yy = 3; yy < own.height - 3 && same; yy += 7)
        for (int xx = 3; xx < own.width - 3 && same; xx += 5)
          same = std::equal(&own.rgb[(static_cast<size_t>(yy) * own.width + xx) * 3],
                            &own.rgb[(static_cast<size_t>(yy) * own.width + xx) * 3 + 3],
                            &png.rgb[(static_cast<size_t>(y + yy) * png.width + x + xx) * 3]);
      found = same;
    }
  EXPECT_TRUE(found);
  // A scale that makes the drawing larger than A0 is refused, naming the key.
  layout.drawing.scale = 1;
  EXPECT_THROW(
      {
        try {
          (void)overview_sheet(layout);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("layout.scale"), std::string::npos);
          throw;
        }
      },
      InputError);
}

}  // namespace
}  // namespace curdle
