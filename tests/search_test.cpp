// Segment measures against brute force and the report, target parsing, and seed search:
// reproducible, independent of threads, and the same through either scoring path.
#include "curdle/search.h"

#include <gtest/gtest.h>

#include <cmath>

#include "search_support.h"

namespace curdle {
TEST(SearchTargets, ParseNamesAndComparisons) {
  const Design d = two_curds_128();
  const Target r = parse_target("ratio:c0+c1=0.25", d);
  EXPECT_EQ(r.measure, Measure::ratio);
  EXPECT_EQ(r.subject, 3);
  EXPECT_EQ(r.compare, Compare::equal);
  EXPECT_DOUBLE_EQ(r.goal, 0.25);
  const Target c = parse_target("cluster:c1<=12", d);
  EXPECT_EQ(c.compare, Compare::at_most);
  EXPECT_EQ(c.subject, 2);
  EXPECT_EQ(parse_target("dimension:c1>=1.5", d).subject, 1);
  EXPECT_EQ(parse_target("count:0=100", d).subject, 0);
  const Target e = parse_target("empty:c0=1,2,3,4", d);
  EXPECT_EQ(e.subject, 0);
  EXPECT_EQ(e.zone, box(1, 2, 3, 4));
  EXPECT_EQ(parse_target("empty=0,0,5,5", d).subject, -1);
  for (const char* bad :
       {"ratio:c0=1.5", "ratio=0.1", "ratio:nope=0.1", "size:c0=3", "dimension:c9=1", "empty=1,2,3",
        "empty=0,0,0,4", "cluster:c0<4", "ratio:c0=-1", "ratio:c0=x", "count:4=1"}) {
    EXPECT_THROW(parse_target(bad, d), InputError) << bad;
  }
  try {
    parse_target("ratio:nope=0.1", d);
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("empty, c0, c1, c0+c1"), std::string::npos)
        << error.what();
  }
}

// Every measure takes a range, LOW..HIGH, met anywhere inside it and ranked by how far inside.
TEST(SearchTargets, EveryMeasureTakesARange) {
  const Design d = two_curds_128();
  for (const char* text : {"ratio:c0=0.22..0.26", "count:c1=100..200", "dimension:c0=1.5..1.7",
                           "cluster:c0=2..9", "run:c1=3..8", "lacunarity:c0=1..2.5"}) {
    const Target t = parse_target(text, d);
    EXPECT_EQ(t.compare, Compare::within) << text;
    EXPECT_LT(t.goal, t.goal_high) << text;
  }
  const Target r = parse_target("ratio:c0=0.22..0.26", d);
  EXPECT_DOUBLE_EQ(shortfall(r, 0.24), 0);
  EXPECT_NEAR(shortfall(r, 0.2), 0.02, 1e-12);
  EXPECT_NEAR(margin(r, 0.24), 0.02, 1e-12);  // further inside ranks first
  EXPECT_GT(margin(r, 0.24), margin(r, 0.255));
  for (const char* bad : {"ratio:c0=0.26..0.22", "ratio:c0=0.5..1.5", "ratio:c0<=0.1..0.2",
                          "count:c0=..5", "count:c0=5..", "ratio:c0=0.1..x"})
    EXPECT_THROW(parse_target(bad, d), InputError) << bad;
}

// sheet_open_area: a range (or bound) every fabrication sheet must meet, measured at the sheet
// that misses most; the layers above lay the sheets out, and without them it is refused.
TEST(SearchTargets, SheetOpenAreaIsARangeEverySheetMustMeet) {
  const Design d = two_curds_128();
  const Target t = parse_target("sheet_open_area=0.25..0.35", d);
  EXPECT_EQ(t.measure, Measure::sheet_open_area);
  EXPECT_EQ(t.compare, Compare::within);
  EXPECT_DOUBLE_EQ(t.goal, 0.25);
  EXPECT_DOUBLE_EQ(t.goal_high, 0.35);
  EXPECT_EQ(parse_target("sheet_open_area>=0.2", d).compare, Compare::at_least);
  for (const char* bad :
       {"sheet_open_area=0.4..0.3", "sheet_open_area=0.2..1.5", "sheet_open_area:c0=0.3",
        "sheet_open_area<=0.2..0.3", "sheet_open_area=x..0.3"})
    EXPECT_THROW(parse_target(bad, d), InputError) << bad;
  EXPECT_DOUBLE_EQ(shortfall(t, 0.3), 0);
  EXPECT_NEAR(shortfall(t, 0.2), 0.05, 1e-12);
  EXPECT_NEAR(shortfall(t, 0.4), 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(worst_sheet(t, {0.3, 0.22, 0.2, 0.38}), 0.2);
  EXPECT_DOUBLE_EQ(worst_sheet(t, {0.3, 0.26}), 0.3);  // all met: the first
  SearchSpec spec;
  spec.targets = {t};
  EXPECT_THROW(check_search(d, box(0, 0, 128, 128), spec), InputError);
  // Met only where every sheet meets it.
  spec.sheet_open_areas = [](const CurdField&, const Box& segment) {
    return segment.origin[0] == 0 ? std::vector<double>{0.3, 0.3} : std::vector<double>{0.3, 0.1};
  };
  spec.window = std::array<int64_t, 2>{64, 64};
  spec.stride = 64;
  spec.top = 1;
  const auto hits = search_seeds(d, box(0, 0, 128, 128), spec, 1, 3);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_EQ(hits[0].score, 0);
  EXPECT_EQ(hits[0].segment.origin[0], 0);
}

// Passes are ranked by how far inside their bounds they are, the tightest sheet deciding:
// 82 seeds of 200 once passed a sheet_open_area band, all scored 0, and came out in seed order.
TEST(SearchTargets, PassesRankByTheirMarginInsideTheBand) {
  const Design d = two_curds_128();
  const Target t = parse_target("sheet_open_area=0.25..0.35", d);
  EXPECT_NEAR(margin(t, 0.3), 0.05, 1e-12);
  EXPECT_NEAR(margin(t, 0.26), 0.01, 1e-12);
  EXPECT_NEAR(margin(t, 0.2), -0.05, 1e-12);
  EXPECT_TRUE(std::isinf(margin(parse_target("ratio:c0=0.2", d), 0.2)));
  SearchSpec spec;
  spec.targets = {t};
  // Seed 1's sheets are nearest the band's edge, seed 3's most central, all pass.
  spec.sheet_open_areas = [](const CurdField& f, const Box&) {
    return f.seed == 1   ? std::vector<double>{0.3, 0.26}
           : f.seed == 2 ? std::vector<double>{0.28, 0.32}
                         : std::vector<double>{0.3, 0.31};
  };
  spec.window = std::array<int64_t, 2>{128, 128};
  spec.top = 3;
  const auto hits = search_seeds(d, box(0, 0, 128, 128), spec, 1, 3);
  ASSERT_EQ(hits.size(), 3u);
  EXPECT_EQ(hits[0].seed, 3u);
  EXPECT_EQ(hits[1].seed, 2u);
  EXPECT_EQ(hits[2].seed, 1u);
  EXPECT_NEAR(hits[0].margin, 0.04, 1e-12);
  EXPECT_NEAR(hits[2].margin, 0.01, 1e-12);
}

TEST(SearchTargets, ShortfallIsZeroWhenMet) {
  const Design d = two_curds_128();
  EXPECT_DOUBLE_EQ(shortfall(parse_target("cluster:c0<=10", d), 8), 0);
  EXPECT_DOUBLE_EQ(shortfall(parse_target("cluster:c0<=10", d), 15), 0.5);
  EXPECT_DOUBLE_EQ(shortfall(parse_target("run:c0>=4", d), 3), 0.25);
  EXPECT_DOUBLE_EQ(shortfall(parse_target("ratio:c0=0.2", d), 0.25), 0.05);
  EXPECT_DOUBLE_EQ(shortfall(parse_target("empty=0,0,10,10", d), 1), 1);  // 100 x 1 / 100
}

TEST(SeedSearch, ThreadCountAndBatchingDoNotChangeTheResult) {
  const Design d = two_curds_128();
  SearchSpec spec;
  spec.targets = {parse_target("ratio:c0+c1=0.1", d), parse_target("cluster:c0+c1<=20", d),
                  parse_target("empty=0,0,6,6", d)};
  spec.window = std::array<int64_t, 2>{40, 30};
  spec.top = 7;
  std::vector<SearchHit> one, many;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = search_seeds(d, d.field, spec, 100, 260);
  }
  many = search_seeds(d, d.field, spec, 100, 260);
  ASSERT_EQ(one.size(), 7u);
  for (size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].seed, many[i].seed);
    EXPECT_EQ(one[i].segment, many[i].segment);
    EXPECT_EQ(one[i].score, many[i].score);
    if (i) {
      EXPECT_LE(one[i - 1].score, one[i].score);
    }
  }
}

TEST(SeedSearch, TheBestHitIsWhatTheReportOfItsSegmentSays) {
  const Design d = two_curds_128();
  SearchSpec spec;
  spec.targets = {parse_target("ratio:c0=0.2", d), parse_target("dimension:c1=1.6", d)};
  spec.window = std::array<int64_t, 2>{64, 48};
  spec.stride = 16;
  spec.top = 3;
  const auto hits = search_seeds(d, d.field, spec, 1, 40);
  ASSERT_EQ(hits.size(), 3u);
  for (const SearchHit& h : hits) {
    const CurdField f = curdle(d, h.seed, h.segment);
    const Report r = make_report(d, h.seed, f, h.segment);
    EXPECT_DOUBLE_EQ(h.measured[0], static_cast<double>(r.values[1].count) / (64 * 48));
    EXPECT_DOUBLE_EQ(h.measured[1], r.curds[1].fit->slope);
    EXPECT_EQ(h.segment.origin[0] % 16 == 0 || h.segment.origin[0] == 200 - 64, true);
  }
  // Exhaustive scoring of one seed finds nothing better than the search's best for it.
  SearchSpec all = spec;
  all.stride = 1;
  const auto exhaustive = search_seeds(d, d.field, all, hits[0].seed, hits[0].seed);
  EXPECT_LE(exhaustive[0].score, hits[0].score);
}

TEST(SeedSearch, BitsetAndGridScoringAgree) {
  // The whole field with ratios and dimensions is scored from bitsets; a segment the size of
  // the field goes through the grid. Both must give the same numbers.
  Design d = test::design(4, 2, {{"2/3", "1/2", "1/3"}});
  SearchSpec fast;
  fast.targets = {parse_target("ratio:c0=0.111", d), parse_target("dimension:c0=1.5", d),
                  parse_target("count:0=3600", d)};
  fast.top = 20;
  SearchSpec grid = fast;
  grid.window = std::array<int64_t, 2>{64, 64};
  const auto a = search_seeds(d, d.field, fast, 0, 500);
  const auto b = search_seeds(d, d.field, grid, 0, 500);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].seed, b[i].seed);
    EXPECT_NEAR(a[i].score, b[i].score, 1e-12);
  }
}

TEST(SeedSearch, RefusesWhatCannotBeSearched) {
  const Design d = two_curds_128();
  SearchSpec spec;
  spec.window = std::array<int64_t, 2>{201, 10};
  EXPECT_THROW(check_search(d, d.field, spec), InputError);
  spec.window = std::array<int64_t, 2>{20, 10};
  spec.targets = {parse_target("empty=15,0,6,6", d)};
  EXPECT_THROW(check_search(d, d.field, spec), InputError);
  spec.targets.clear();
  spec.top = 0;
  EXPECT_THROW(check_search(d, d.field, spec), InputError);
  Design cube = test::design(2, 3, test::repeat("0.5", 3));
  EXPECT_THROW(check_search(cube, cube.field, SearchSpec{}), InputError);
}

TEST(SeedSearch, DefaultTargetsAreTheExpectedSharesAndDimensions) {
  const Design d = test::design(4, 2, {{"2/3", "1/2", "1/3"}});
  const auto t = default_targets(d);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_NEAR(t[1].goal, 1.0 / 9, 1e-12);
  EXPECT_NEAR(t[0].goal, 8.0 / 9, 1e-12);
  EXPECT_NEAR(t[2].goal, 2 + std::log(1.0 / 9) / (3 * std::log(4.0)), 1e-12);
}

}  // namespace curdle
