// Tests of coursing.h: courses run level round the pavilion with one joint between units all the
// way round (the closing corner too), every corner turned by one unit a course, the outer
// corners' quoins changing sides course by course so that stretcher bond laps by half a unit at
// every corner, the inner corners' through units likewise, cuts never below the narrowest
// allowed, and a free-standing wall's stopped ends.
#include "building/coursing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "building/facades.h"
#include "building_support.h"
#include "curdle/error.h"
#include "kinds/registry.h"
#include "layout/contour.h"

namespace curdle {
namespace {

Envelope pavilion(const LayoutSpec& spec) {
  BuildingKeys keys;
  keys.plan =
      contour_of({{0, 0}, {20000, 0}, {20000, 6000}, {12000, 6000}, {12000, 12000}, {0, 12000}});
  keys.height = 7050;
  return envelope_of(keys, spec);
}

// A free-standing wall 9 m long and ten courses high.
Envelope free_standing_wall(const LayoutSpec& spec) {
  BuildingKeys keys;
  keys.path = {{0, 0, 0}, {9000, 0, 0}};
  keys.height = 750;
  return envelope_of(keys, spec);
}

std::map<int64_t, std::vector<CourseUnit>> by_course(const Coursing& c) {
  std::map<int64_t, std::vector<CourseUnit>> out;
  for (const CourseUnit& u : c.units) out[u.course].push_back(u);
  return out;
}

TEST(Coursing, EveryCourseGoesRoundTheBuildingWithOneJointBetweenUnits) {
  const LayoutSpec spec = test::bricks();
  const Envelope env = pavilion(spec);
  ASSERT_EQ(env.courses, 94);
  const Coursing c = course_envelope(env, spec, CourseBond::stretcher);
  const auto courses = by_course(c);
  ASSERT_EQ(courses.size(), 94u);
  for (const auto& [r, units] : courses) {
    double faces = 0;
    for (size_t k = 0; k < units.size(); ++k) {
      const CourseUnit& a = units[k];
      // The next unit round the strip; the last one's joint is the closing corner's.
      const double next = k + 1 < units.size() ? units[k + 1].from : units[0].from + env.length;
      EXPECT_NEAR(next - a.to, 10, 1e-6) << "course " << r << " unit " << k;
      EXPECT_GE(a.to - a.from, 215.0 / 3 - 1e-6);
      faces += a.to - a.from;
    }
    EXPECT_NEAR(faces + 10.0 * units.size(), env.length, 1e-6) << "course " << r;
  }
}

TEST(Coursing, EveryBondGoesRoundTheBuildingWithOneJointBetweenUnits) {
  const LayoutSpec spec = test::bricks();
  const Envelope env = pavilion(spec);
  for (CourseBond bond : {CourseBond::stack, CourseBond::third, CourseBond::quarter,
                          CourseBond::english, CourseBond::flemish}) {
    const auto courses = by_course(course_envelope(env, spec, bond));
    ASSERT_EQ(courses.size(), 94u);
    for (const auto& [r, units] : courses) {
      std::map<int, int> turned;
      for (size_t k = 0; k < units.size(); ++k) {
        const CourseUnit& a = units[k];
        const double next = k + 1 < units.size() ? units[k + 1].from : units[0].from + env.length;
        ASSERT_NEAR(next - a.to, 10, 1e-6) << int(bond) << " course " << r << " unit " << k;
        // No piece under the narrowest cut but a queen closer, half a header.
        EXPECT_GE(a.to - a.from, 46.25 - 1e-6) << int(bond) << " course " << r;
        turned[a.corner] += a.role == UnitRole::corner;
      }
      for (int c = 0; c < 6; ++c) EXPECT_EQ(turned[c], 1) << int(bond) << " corner " << c;
    }
  }
}

// The pieces of course r wholly on façade k that are neither corner units nor closers.
std::vector<CourseUnit> run_of(const std::vector<CourseUnit>& course, const SurfaceFrame& f) {
  std::vector<CourseUnit> out;
  for (const CourseUnit& u : course)
    if (u.role != UnitRole::corner && u.role != UnitRole::closer && u.from >= f.start &&
        u.to <= f.start + f.length)
      out.push_back(u);
  return out;
}

TEST(Coursing, EnglishBondLaysCoursesOfStretchersAndOfHeadersByTurnsLappingByAQuarter) {
  const LayoutSpec spec = test::bricks();
  const Envelope env = pavilion(spec);
  const auto courses = by_course(course_envelope(env, spec, CourseBond::english));
  for (const auto& [r, units] : courses)
    for (size_t k = 0; k < 6; ++k) {
      const SurfaceFrame& f = env.facades[k];
      const bool headers = (r + static_cast<int64_t>(k)) % 2 == 1;
      for (const CourseUnit& u : run_of(units, f)) {
        ASSERT_EQ(u.role, headers ? UnitRole::header : UnitRole::stretcher) << r << " " << k;
        EXPECT_NEAR(u.depth, headers ? 215 : 0, 1e-9);
      }
      if (!headers) continue;
      // A queen closer beside the corner unit at the façade's end, outer or inner.
      const double end = f.start + f.length;
      for (size_t i = 0; i + 1 < units.size(); ++i)
        if (units[i + 1].role == UnitRole::corner && units[i + 1].corner == int(k)) {
          EXPECT_NEAR(units[i].to - units[i].from, 46.25, 1e-9) << r << " " << k;
          // The quoin's header at an outer corner; at the inner one the other face's unit runs
          // through.
          EXPECT_NEAR(end - units[i + 1].from, f.turn_at_end > 0 ? 102.5 : 0, 1e-9);
        }
    }
  // Over the south face's first 2 m, every joint of a stretcher course lies under the middle
  // of a header of the course above: the quarter lap.
  for (int64_t r = 0; r + 1 < 94; r += 2) {
    for (const CourseUnit& s : courses.at(r)) {
      if (s.to > 2000 || s.from < 0) continue;
      bool centred = false;
      for (const CourseUnit& h : courses.at(r + 1))
        centred |= h.role == UnitRole::header && std::fabs((h.from + h.to) / 2 - s.to - 5) < 1e-6;
      EXPECT_TRUE(centred) << "course " << r << " joint at " << s.to + 5;
    }
  }
}

TEST(Coursing, FlemishBondAlternatesHeadersAndStretchersEachHeaderCentredOnAStretcher) {
  const LayoutSpec spec = test::bricks();
  const Envelope env = pavilion(spec);
  const auto courses = by_course(course_envelope(env, spec, CourseBond::flemish));
  for (const auto& [r, units] : courses) {
    std::vector<CourseUnit> near;  // the south face's first 2 m, past the corner's pieces
    for (const CourseUnit& u : run_of(units, env.facades[0]))
      if (u.to < 2000) near.push_back(u);
    ASSERT_GE(near.size(), 6u);
    for (size_t i = 1; i < near.size(); ++i)
      EXPECT_NE(near[i].role, near[i - 1].role) << "course " << r << " piece " << i;
    if (r == 0) continue;
    for (const CourseUnit& h : near) {
      if (h.role != UnitRole::header) continue;
      bool centred = false;
      for (const CourseUnit& s : courses.at(r - 1))
        centred |= s.role == UnitRole::stretcher &&
                   std::fabs((s.from + s.to) / 2 - (h.from + h.to) / 2) < 1e-6;
      EXPECT_TRUE(centred) << "course " << r << " header at " << h.from;
    }
  }
}

TEST(Coursing, ThirdAndQuarterBondMoveEachCourseAlongByTheirShare) {
  const LayoutSpec spec = test::bricks();
  const Envelope env = pavilion(spec);
  for (const auto& [bond, share] :
       {std::pair{CourseBond::third, 1.0 / 3}, std::pair{CourseBond::quarter, 0.25}}) {
    size_t whole = 0;
    for (const CourseUnit& u : course_envelope(env, spec, bond).units) {
      if (u.role != UnitRole::stretcher) continue;
      ++whole;
      const double phase = std::fmod(static_cast<double>(u.course) * share, 1.0) * 225;
      const double off = std::fmod(u.from - phase + 225 * 1000, 225);
      EXPECT_TRUE(off < 1e-6 || off > 225 - 1e-6) << u.course << " at " << u.from;
    }
    EXPECT_GT(whole, 20000u);
  }
}

TEST(Coursing, EachCornerIsTurnedByOneUnitACourseChangingSides) {
  const LayoutSpec spec = test::bricks();
  const Envelope env = pavilion(spec);
  const Coursing c = course_envelope(env, spec, CourseBond::stretcher);
  const auto courses = by_course(c);
  for (const auto& [r, units] : courses) {
    std::map<int, int> turned;
    for (const CourseUnit& u : units)
      if (u.role == UnitRole::corner) {
        ++turned[u.corner];
        const SurfaceFrame& f = env.facades[static_cast<size_t>(u.corner)];
        const double at = f.start + f.length, before = at - u.from, after = u.to - at;
        const bool first = (r + u.corner) % 2 == 0;
        if (f.turn_at_end > 0) {  // outer: stretcher and header, sides changing
          EXPECT_NEAR(before, first ? 215 : 102.5, 1e-9);
          EXPECT_NEAR(after, first ? 102.5 : 215, 1e-9);
        } else {  // inner: the through unit shows 112.5 mm on one side only
          EXPECT_NEAR(before, first ? 112.5 : 0, 1e-9);
          EXPECT_NEAR(after, first ? 0 : 112.5, 1e-9);
        }
      }
    EXPECT_EQ(turned.size(), 6u);
    for (const auto& [corner, n] : turned) EXPECT_EQ(n, 1) << "corner " << corner;
  }
  // The first joint past each corner moves by half a unit's pitch from course to course.
  for (int64_t r = 0; r + 1 < 94; ++r)
    for (const CourseUnit& a : courses.at(r))
      if (a.role == UnitRole::corner && a.corner < 5)
        for (const CourseUnit& b : courses.at(r + 1))
          if (b.role == UnitRole::corner && b.corner == a.corner) {
            EXPECT_NEAR(std::fabs(b.to - a.to), 112.5, 1e-9);
          }
}

TEST(Coursing, RunsAreCutInTheirMiddleAndNeverBelowTheNarrowestCut) {
  const LayoutSpec spec = test::bricks();
  const Envelope env = pavilion(spec);
  const Coursing c = course_envelope(env, spec, CourseBond::stretcher);
  size_t closers = 0;
  for (const CourseUnit& u : c.units) {
    if (u.role != UnitRole::closer) continue;
    ++closers;
    EXPECT_GE(u.to - u.from, 215.0 / 3 - 1e-9);
    EXPECT_LT(u.to - u.from, 215);
    // In the middle third of its façade.
    const SurfaceFrame* f = frame_at(env.facades, (u.from + u.to) / 2);
    const double along = (u.from + u.to) / 2 - f->start;
    EXPECT_GT(along, f->length / 4);
    EXPECT_LT(along, f->length * 3 / 4);
  }
  EXPECT_GT(closers, 0u);
}

TEST(Coursing, StackBondTurnsEveryCornerAlike) {
  const LayoutSpec spec = test::bricks();
  const Envelope env = pavilion(spec);
  const Coursing c = course_envelope(env, spec, CourseBond::stack);
  for (const CourseUnit& u : c.units)
    if (u.role == UnitRole::corner && u.corner == 0) {
      EXPECT_NEAR(20000 - u.from, 215, 1e-9);
      EXPECT_NEAR(u.to - 20000, 102.5, 1e-9);
    }
}

TEST(Coursing, AFreeStandingWallHasStoppedEndsWithHalfUnitsOnAlternateCourses) {
  const LayoutSpec spec = test::bricks();
  const Envelope env = free_standing_wall(spec);
  EXPECT_FALSE(env.closed);
  const auto courses = by_course(course_envelope(env, spec, CourseBond::stretcher));
  ASSERT_EQ(courses.size(), 10u);
  for (const auto& [r, units] : courses) {
    EXPECT_NEAR(units.front().from, 0, 1e-9);
    EXPECT_NEAR(units.back().to, 9000, 1e-9);
    EXPECT_EQ(units.front().role == UnitRole::end, r % 2 == 1);
    if (r % 2 == 1) {
      EXPECT_NEAR(units.front().to, 102.5, 1e-9);
    }
  }
}

TEST(Coursing, AFreeStandingWallInEnglishOrFlemishBondStopsWithAHeaderAndQueenCloser) {
  const LayoutSpec spec = test::bricks();
  const Envelope env = free_standing_wall(spec);
  for (CourseBond bond : {CourseBond::english, CourseBond::flemish}) {
    const auto courses = by_course(course_envelope(env, spec, bond));
    for (const auto& [r, units] : courses) {
      // Each end of the wall: a stretcher, or a header and a queen closer, by courses (in
      // English bond the header courses, in Flemish every other course).
      const bool headers = r % 2 == 1;
      ASSERT_GE(units.size(), 4u);
      EXPECT_NEAR(units.front().from, 0, 1e-9);
      EXPECT_NEAR(units.back().to, 9000, 1e-9);
      EXPECT_EQ(units[0].role, headers ? UnitRole::header : UnitRole::stretcher)
          << int(bond) << " course " << r;
      if (headers) {
        EXPECT_NEAR(units[1].to - units[1].from, 46.25, 1e-9) << int(bond) << " course " << r;
        EXPECT_NEAR(units[units.size() - 2].to - units[units.size() - 2].from, 46.25, 1e-9);
        EXPECT_EQ(units.back().role, UnitRole::header);
      } else {
        EXPECT_EQ(units.back().role, UnitRole::stretcher);
      }
    }
  }
}

TEST(Coursing, CornersAreDescribedForTheReport) {
  const LayoutSpec spec = test::bricks();
  const Coursing c = course_envelope(pavilion(spec), spec, CourseBond::stretcher);
  size_t outer = 0, inner = 0;
  for (const std::string& n : c.notes) {
    outer += n.find("an outer corner of 90.0°") != std::string::npos;
    inner += n.find("an inner corner of 90.0°") != std::string::npos;
  }
  EXPECT_EQ(outer, 5u);
  EXPECT_EQ(inner, 1u);
  EXPECT_STREQ(corner_kind(5), "bend");
  EXPECT_STREQ(corner_kind(-90), "inner");
}

TEST(Coursing, AFacadeTooShortForTheUnitsTurningItsCornersIsRefused) {
  const LayoutSpec spec = test::bricks();
  BuildingKeys keys;
  // A 300 mm jog: an outer corner then an inner one, 215 + 112.5 + 10 mm needed on one course.
  keys.plan = contour_of({{0, 0}, {5000, 0}, {5000, 300}, {5300, 300}, {5300, 3000}, {0, 3000}});
  keys.height = 750;
  try {
    check_corner_room(envelope_of(keys, spec), spec);
    ADD_FAILURE() << "a 300 mm façade between corners was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "plan");
    EXPECT_NE(e.message().find("façade E is 300 mm long, too short for the units that turn its "
                               "corners: at least 337.5 mm"),
              std::string::npos)
        << e.message();
  }
  keys.plan = contour_of({{0, 0}, {5000, 0}, {5000, 440}, {0, 440}});  // 2 x 215 + 10: room
  EXPECT_NO_THROW(check_corner_room(envelope_of(keys, spec), spec));
}

}  // namespace
}  // namespace curdle
