// Density fields: survival follows the field (statistically, over fixed seeds), the report's
// expectations are exact, the field lies where the layout lays each cell, and bad fields are
// refused with what is allowed.
#include "curdle/density.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/run.h"
#include "curdle/boxcount.h"
#include "curdle/curdling.h"
#include "curdle/error.h"
#include "curdle/report.h"
#include "export/image.h"
#include "layout/builder.h"
#include "layout/cell_placement.h"
#include "recipe/recipe.h"
#include "test_support.h"

namespace curdle {
namespace {

// One 64 x 64 root (base 4, 3 stages), P_K = 1/3, thickening toward the middle: 0.9 at the
// centre, 0.05 from 32 cells out.
Design radial_design() {
  Design d = test::design(4, 2, {{"3/4", "2/3", "2/3"}});
  DensityField f;
  f.kind = DensityKind::radial;
  f.centre = {32, 32, 0};
  f.radius = 32;
  f.values = {2.7, 0.15};
  d.curds[0].density = f;
  return d;
}

double distance_from_centre(int64_t x, int64_t y) {
  return std::hypot(static_cast<double>(x) + 0.5 - 32, static_cast<double>(y) + 0.5 - 32);
}

}  // namespace

// Over 200 fixed seeds, the share of surviving cells in each ring around the centre is the
// mean of min(1, P_K g) over the ring's cells. Ignoring the field (every ring at 1/3) misses
// the inner ring by 0.5 and the outer by 0.28; the rings' observed errors are about 0.01.
TEST(Density, SurvivalFollowsTheFieldInEveryRing) {
  const Design d = radial_design();
  const DensityField& f = *d.curds[0].density;
  constexpr int kRings = 4;
  std::array<double, kRings> expected{}, alive{};
  std::array<int64_t, kRings> cells{};
  auto ring = [](int64_t x, int64_t y) {
    return std::min(kRings - 1, static_cast<int>(distance_from_centre(x, y) / 8));
  };
  for (int64_t y = 0; y < 64; ++y)
    for (int64_t x = 0; x < 64; ++x) {
      expected[ring(x, y)] += std::min(1.0, f.at_cell({x, y, 0}) / 3);
      ++cells[ring(x, y)];
    }
  constexpr int kSeeds = 200;
  CurdField field;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    curdle_into(d, seed, d.field, field);
    for (int64_t y = 0; y < 64; ++y)
      for (int64_t x = 0; x < 64; ++x) alive[ring(x, y)] += field.value_at({x, y, 0});
  }
  for (int r = 0; r < kRings; ++r) {
    const double want = expected[r] / cells[r], got = alive[r] / (cells[r] * kSeeds);
    EXPECT_NEAR(got, want, 0.05) << "ring " << r;
  }
  // The field falls outwards, and so do the shares.
  EXPECT_GT(alive[0] / cells[0], 2 * alive[3] / cells[3]);
}

// The report's expected survivors, their spread and the expected box counts agree with the
// means and spread over 200 seeds (bounds of about five standard errors).
TEST(Density, ReportExpectationsMatchTheMeansOverSeeds) {
  const Design d = radial_design();
  constexpr int kSeeds = 200;
  const int K = d.lattice.stages;
  std::vector<double> sum(K + 1), sum2(K + 1), boxes(K + 1);
  Report report;
  CurdField field;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    curdle_into(d, seed, d.field, field);
    report = make_report(d, seed, field, d.field);
    const CurdReport& c = report.curds[0];
    for (int k = 1; k <= K; ++k) {
      const double n = static_cast<double>(c.stages[k - 1].survivors);
      sum[k] += n;
      sum2[k] += n * n;
      boxes[k] += static_cast<double>(c.box_counts[k]);
    }
  }
  const CurdReport& c = report.curds[0];
  for (int k = 1; k <= K; ++k) {
    const StageRow& row = c.stages[k - 1];
    const double mean = sum[k] / kSeeds;
    const double sd = std::sqrt(sum2[k] / kSeeds - mean * mean);
    EXPECT_NEAR(mean, row.expected, 5 * row.expected_sd / std::sqrt(kSeeds)) << "stage " << k;
    EXPECT_NEAR(sd, row.expected_sd, 0.3 * row.expected_sd) << "stage " << k;
    EXPECT_NEAR(boxes[k] / kSeeds, c.expected_box_counts[k],
                5 * row.expected_sd / std::sqrt(kSeeds) + 1)
        << "stage " << k;
  }
  // The final expectation is the sum of min(1, P_K g) over the cells.
  double final_sum = 0;
  for (int64_t y = 0; y < 64; ++y)
    for (int64_t x = 0; x < 64; ++x)
      final_sum += std::min(1.0, d.curds[0].density->at_cell({x, y, 0}) / 3);
  EXPECT_NEAR(c.stages.back().expected, final_sum, 1e-6);
  EXPECT_NEAR(report.values[1].expected, final_sum, 1e-6);
}

// g = 1 everywhere is the plain curd: with halves every ratio of products is exact, so even
// the bits agree.
TEST(Density, AFieldOfOneIsThePlainCurd) {
  Design plain = test::design(2, 2, test::repeat("1/2", 6));
  Design flat = plain;
  DensityField f;
  f.kind = DensityKind::linear;
  f.to = {64, 0, 0};
  f.values = {1, 1};
  flat.curds[0].density = f;
  for (uint64_t seed : {1, 7, 99}) {
    const CurdField a = curdle(plain, seed, plain.field), b = curdle(flat, seed, flat.field);
    EXPECT_TRUE(a.finest(0).words == b.finest(0).words) << "seed " << seed;
  }
}

// A stage-k bound is never below its children's, so q_k never exceeds 1.
TEST(Density, EveryCellsBoundHoldsItsChildren) {
  for (DensityKind kind : {DensityKind::linear, DensityKind::radial}) {
    Design d = radial_design();
    DensityField& f = *d.curds[0].density;
    f.kind = kind;
    f.from = {5, 60, 0};
    f.to = {50, 3, 0};
    f.values = {0.1, 3};
    f.placement.course_shift = {0, -0.5};
    for (int k = 1; k <= d.lattice.stages; ++k) {
      const int64_t n = 1 << (2 * k);
      const double P = std::pow(0.75, 1) * (k > 1 ? std::pow(2.0 / 3, k - 1) : 1);
      const double Pp = k == 1 ? 1 : std::pow(0.75, 1) * (k > 2 ? std::pow(2.0 / 3, k - 2) : 1);
      for (int64_t y = 0; y < n; ++y)
        for (int64_t x = 0; x < n; ++x) {
          const double child = f.survival(d.lattice, k, {x, y, 0}, P);
          const double parent = f.survival(d.lattice, k - 1, {x / 4, y / 4, 0}, Pp);
          ASSERT_LE(child, parent + 1e-12) << "stage " << k << " cell " << x << "," << y;
        }
    }
  }
}

// The field is read where the layout lays each cell: every element's centre, for every corner,
// bond, centring and window.
TEST(Density, PlacementIsWhereTheLayoutLaysEachCell) {
  const Design d = test::design(4, 2, {{"1/2", "1/2", "1/2", "1/2"}});
  for (const char* corner : {"bottom-left", "bottom-right", "top-left", "top-right", "centre"})
    for (const char* bond : {"stack", "half", "third"}) {
      std::string text = std::string(R"(name = "p"
[lattice]
base = 4
dimension = 2
[[curds]]
probabilities = ["1/2", "1/2", "1/2", "1/2"]
[field]
cells = [256, 256]
[layout]
kind = "paving"
tile = [600, 300]
joint = 5
floor = [12000, 5500]
bond = ")") + bond + "\"\norigin = \"" +
                         corner + "\"\n";
      if (std::string(corner) != "centre") text += "shift = [100, 50]\n";
      Recipe r;
      try {  // laid from a window away from the field's origin
        const auto need = elements_to_cover(*parse_recipe(text, "p.toml").layout);
        r = parse_recipe(text, "p.toml",
                         {"field.window=[13, 7, " + std::to_string(need[0]) + ", " +
                          std::to_string(need[1]) + "]"});
      } catch (const InputError& e) {
        FAIL() << corner << " " << bond << ": " << e.what();
      }
      const CellPlacement p = cell_placement(*r.layout, *r.window);
      const Layout layout =
          make_layout(r.design, curdle(r.design, 1, *r.window), *r.window, *r.layout);
      ASSERT_GT(layout.elements.size(), 100u);
      for (const Element& e : layout.elements) {
        const auto c = p.centre({e.cell_x, e.cell_y, 0}, 2);
        ASSERT_NEAR(c[0], e.nominal.x + e.nominal.w / 2, 1e-6)
            << corner << " " << bond << " " << e.id;
        ASSERT_NEAR(c[1], e.nominal.y + e.nominal.h / 2, 1e-6)
            << corner << " " << bond << " " << e.id;
      }
    }
}

// An image field: a picture black on its left half and white on its right, values [0, 3] on a
// curd of P_K = 1/3: every cell under white survives and none under black.
TEST(Density, AnImageFieldIsReadRelativeToTheRecipe) {
  const auto dir = std::filesystem::temp_directory_path() / "curdle_density_image";
  std::filesystem::create_directories(dir);
  PreviewImage picture;
  picture.width = 8;
  picture.height = 4;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x)
      for (int ch = 0; ch < 3; ++ch) picture.rgb.push_back(x < 4 ? 0 : 255);
  std::ofstream(dir / "half.png", std::ios::binary) << encode_png(picture);
  app::RunRequest request;
  request.recipe_path = (dir / "r.toml").string();
  request.recipe_text = R"(name = "image"
[lattice]
base = 2
dimension = 2
[[curds]]
probabilities = ["1/2", "2/3"]
[curds.density]
kind = "image"
path = "half.png"
values = [0, 3]
)";
  const app::Run run = app::resolve_run(request);
  const CurdField field = app::run_engine(run, 1);
  for (int64_t y = 0; y < 4; ++y)
    for (int64_t x = 0; x < 4; ++x) EXPECT_EQ(field.value_at({x, y, 0}), x < 2 ? 0u : 1u);
  request.recipe_text.replace(request.recipe_text.find("half.png"), 8, "gone.png");
  try {
    app::resolve_run(request);
    ADD_FAILURE() << "a missing image was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("curds.0.density.path"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(Density, BadFieldsAreRefusedSayingWhatIsAllowed) {
  const std::string head = R"(name = "t"
[lattice]
base = 2
dimension = 2
mode = "MODE"
[[curds]]
probabilities = ["1/2", "1/2"]
[curds.density]
)";
  auto error_of = [&](const std::string& body, const std::string& mode = "canonical") {
    std::string text = head;
    text.replace(text.find("MODE"), 4, mode);
    try {
      parse_recipe(text + body, "r.toml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"kind = \"wave\"\n", "\"linear\", \"radial\" or \"image\""},
      {"values = [1, 2]\n", "kind"},
      {"kind = \"linear\"\nfrom = [0, 0]\nto = [0, 0]\nvalues = [1, 2]\n", "must differ"},
      {"kind = \"linear\"\nfrom = [0, 0]\nto = [4, 0]\nvalues = [1, -2]\n", "from 0 to 1000"},
      {"kind = \"linear\"\nfrom = [0, nan]\nto = [4, 0]\nvalues = [1, 2]\n", "finite"},
      {"kind = \"linear\"\nfrom = [0, 0, 0]\nto = [4, 0]\nvalues = [1, 2]\n", "[x, y] in cells"},
      {"kind = \"linear\"\nfrom = [0, 0]\nto = [4, 0]\nvalues = [1, inf]\n", "from 0 to 1000"},
      {"kind = \"radial\"\ncentre = [0, 0]\nradius = 0\nvalues = [1, 2]\n", "above 0"},
      {"kind = \"radial\"\ncentre = [0, 0]\nradius = 3\nfrom = [1, 1]\nvalues = [1, 2]\n",
       "belongs to kind \"linear\""},
      {"kind = \"image\"\nvalues = [1, 2]\n", "path"},
      {"kind = \"image\"\npath = \"a.png\"\nrect = [0, 0, 0, 4]\nvalues = [1, 2]\n",
       "sizes above 0"},
      {"kind = \"radial\"\ncentre = [0, 0]\nradius = 3\nvalues = [1, 2]\ncolour = 1\n", "colour"},
  };
  for (const auto& [body, want] : cases) {
    const std::string got = error_of(body);
    EXPECT_NE(got.find(want), std::string::npos) << body << " -> " << got;
    EXPECT_NE(got.find("curds.0.density"), std::string::npos) << body << " -> " << got;
  }
  const std::string exact =
      error_of("kind = \"radial\"\ncentre = [0, 0]\nradius = 3\nvalues = [1, 2]\n", "exact");
  EXPECT_NE(exact.find("lattice.mode = \"canonical\""), std::string::npos) << exact;
}

}  // namespace curdle
