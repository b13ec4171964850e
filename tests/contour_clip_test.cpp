#include "layout/contour_clip.h"

#include <gtest/gtest.h>

#include "layout/box_clip.h"
#include "layout/zone.h"

namespace curdle {
namespace {

// A 14 x 9 m floor whose top edge is an arch dipping 1.4 m (bulge -0.2 on a 14 m chord: a radius
// of 18.2 m, centred 25.8 m up).
const Contour kArched{{0, 0, 0}, {14000, 0, 0}, {14000, 9000, -0.2}, {0, 9000, 0}};

// The area of the part, from a polygon of the contour's chords at a micrometre (which miss the
// true arc's area by about two thirds of its length times that: some 9 mm² here).
double fine_area(const Contour& c, const Rect& box) {
  return polygon_area(*clip_to_box(flatten(c, 0.001), box));
}

TEST(ContourClipTest, ArcsCrossingTheBoxAreSplitNotChorded) {
  for (const Rect& box :
       {Rect{0, 0, 5000, 9500}, Rect{4000, 7000, 6000, 2500}, Rect{10000, 4000, 5000, 6000}}) {
    const auto part = clip_contour_to_box(kArched, box, 0.05);
    ASSERT_TRUE(part);
    EXPECT_GT(arc_count(*part), 0u);
    EXPECT_NEAR(contour_area(*part), fine_area(kArched, box), 20.0) << box.x << " " << box.y;
    for (const ContourVertex& v : *part) {
      EXPECT_GE(v.x, box.x - 1e-9);
      EXPECT_LE(v.x, box.right() + 1e-9);
      EXPECT_GE(v.y, box.y - 1e-9);
      EXPECT_LE(v.y, box.top() + 1e-9);
    }
    // Every arc of the part lies on the outline's circle.
    for (size_t i = 0; i < part->size(); ++i)
      if ((*part)[i].bulge != 0) {
        const Arc a = arc_between((*part)[i], (*part)[(i + 1) % part->size()]);
        EXPECT_NEAR(a.radius, 18200, 1e-6);
        EXPECT_NEAR(a.centre[1], 25800, 1e-6);
      }
  }
}

TEST(ContourClipTest, OutsideInsideAndSeveralPieces) {
  EXPECT_EQ(clip_contour_to_box(kArched, Rect{20000, 0, 10, 10}, 0.05), Contour{});
  const auto whole = clip_contour_to_box(kArched, Rect{-10, -10, 20000, 20000}, 0.05);
  ASSERT_TRUE(whole);
  EXPECT_NEAR(contour_area(*whole), contour_area(kArched), 1e-6);
  // A disc's lower half: its lower arc kept whole, closed along the box's side.
  const Contour disc{{-100, 0, 1}, {100, 0, 1}};
  const auto half = clip_contour_to_box(disc, Rect{-200, -200, 400, 200}, 0.05);
  ASSERT_TRUE(half);
  EXPECT_EQ(arc_count(*half), 1u);
  EXPECT_NEAR(contour_area(*half), 3.14159265358979323846 * 100 * 100 / 2, 1e-6);
  // A quarter: the lower arc split where it crosses x = 0.
  const auto quarter = clip_contour_to_box(disc, Rect{0, -200, 200, 200}, 0.05);
  ASSERT_TRUE(quarter);
  EXPECT_NEAR(contour_area(*quarter), 3.14159265358979323846 * 100 * 100 / 4, 1e-6);
  // A U whose two arms reach into the box: two pieces, left to the chords.
  const Contour u{{0, 0, 0},   {90, 0, 0},  {90, 90, 0}, {60, 90, 0},
                  {60, 30, 0}, {30, 30, 0}, {30, 90, 0}, {0, 90, 0}};
  EXPECT_FALSE(clip_contour_to_box(u, Rect{10, 50, 70, 20}, 0.05));
}

}  // namespace
}  // namespace curdle
