// Tests of fit_run.h: probabilities as recipes write them, options checked first, and a fitted
// recipe written whole.
#include "app/fit_run.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <sstream>

#include "curdle/curdling.h"
#include "curdle/error.h"
#include "export/report/cells_csv.h"
#include "picture_support.h"

namespace curdle::app {
namespace {

TEST(FitRun, OptionsProbabilitiesAndTheRecipeWritten) {
  EXPECT_EQ(probability_text(0.5), "0.5000");
  EXPECT_EQ(probability_text(0.61237), "0.6124");
  FitRequest bad;
  bad.stages = 0;
  EXPECT_THROW(check_fit_options(bad), InputError);
  bad.stages = 3, bad.curds = 0;
  EXPECT_THROW(check_fit_options(bad), InputError);
  // b^K past 64 bits once wrapped to 0 and was divided by (SIGFPE): refused, naming stages.
  for (const auto& [base, stages] : {std::pair{64, 30}, {16, 16}, {8, 22}, {4, 20}}) {
    FitRequest deep;
    deep.base = base, deep.stages = stages;
    try {
      check_fit_options(deep);
      ADD_FAILURE() << base << "^" << stages << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().parameter, "stages");
      EXPECT_NE(e.message().find("stages with this base"), std::string::npos) << e.what();
    }
  }
  FitRequest deepest_allowed;
  deepest_allowed.base = 2, deepest_allowed.stages = 30;  // 2^60 cells to a root in 2-D
  EXPECT_NO_THROW(check_fit_options(deepest_allowed));
  EXPECT_THROW(check_fit_lattice(Lattice{2, 3, 30, Mode::canonical}), InputError);  // a 3-D csv

  const auto dir = test::scratch("fit-run");
  FitRequest request;
  request.source = test::write_file(dir / "checker.png", test::grey_png(8, 8, [](int x, int y) {
                                      return (x / 4 + y / 4) % 2 ? 255 : 0;
                                    }));
  request.stages = 3;
  EXPECT_EQ(run_fit(request).size[0], 2);  // its cells are found to be 4 x 4 pixels
  request.cell_pixels = 1;                 // a pixel a cell, as asked
  const FittedRecipe fitted = run_fit(request);
  EXPECT_EQ(fitted.size[0], 8);
  const std::string where = write_fitted_recipe(fitted, (dir / "out" / "fitted.toml").string());
  std::ifstream in(where);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), fitted.toml);
  // A file name cannot write keys into the recipe: its comment stays one line.
  FitRequest crafted = request;
  crafted.source =
      test::write_file(dir / "x\n[lattice]\nbase = 3\n.png",
                       test::grey_png(8, 8, [](int x, int) { return x < 4 ? 0 : 255; }));
  const FittedRecipe safe = run_fit(crafted);
  EXPECT_EQ(safe.toml.find("\nbase = 3"), std::string::npos) << safe.toml;
  EXPECT_NE(safe.toml.find("\nbase = 2\n"), std::string::npos) << safe.toml;
  std::filesystem::remove_all(dir);
}

// A cells.csv of a window keeps its place on the lattice: fitted where the report counts it.
// (Its origin dropped, the fit of p_8 = 0.7 was 0.33.)
TEST(FitRun, AWindowsCellsAreFittedWhereTheyLie) {
  Design d;
  d.name = "window";
  d.lattice = Lattice{2, 2, 8, Mode::canonical};
  d.curds = {CurdSpec{"c", std::vector<Probability>(8, *Probability::parse("0.7"))}};
  d.field = Box{{0, 0, 0}, {256, 256, 1}};
  const Box window{{10, 13, 0}, {100, 77, 1}};
  const auto dir = test::scratch("fit-run-window");
  for (const uint64_t seed : {1u, 2u, 3u}) {
    std::ostringstream csv;
    write_cells_csv(csv, d, curdle(d, seed, window), window);
    FitRequest r;
    r.source = test::write_file(dir / "cells.csv", csv.str()).string();
    r.stages = 8;
    const FittedRecipe f = run_fit(r);
    ASSERT_EQ(f.curds.size(), 1u);
    const std::vector<StageFit>& stages = f.curds[0].fit.stages;
    EXPECT_EQ(stages[0].low, 0.0);  // the window lies in one stage-1 cell: nothing to know
    EXPECT_EQ(stages[0].high, 1.0);
    for (size_t k = 1; k < stages.size(); ++k) {
      const double se = (stages[k].high - stages[k].low) / 3.92;
      EXPECT_NEAR(stages[k].probability, 0.7, 4 * se) << "seed " << seed << " stage " << k + 1;
    }
    EXPECT_TRUE(f.warnings.empty()) << f.warnings[0];
  }
  std::filesystem::remove_all(dir);
}

// Pictures no curd explains get a warning naming the stages that fail and which way, in the
// result and in the recipe's text; blank and full pictures are refused; a curd passes.
TEST(FitRun, PicturesThatAreNotCurdsAreSaidSo) {
  const auto dir = test::scratch("fit-run-not-curds");
  auto fit = [&](const std::string& name, const std::function<uint8_t(int, int)>& grey) {
    FitRequest r;
    r.source = test::write_file(dir / (name + ".png"), test::grey_png(64, 64, grey)).string();
    r.stages = 6;
    return run_fit(r);
  };
  const std::vector<std::pair<std::string, std::function<uint8_t(int, int)>>> not_curds{
      {"gradient", [](int x, int y) { return static_cast<uint8_t>(2 * x + y); }},
      {"disk",
       [](int x, int y) { return (x - 30) * (x - 30) + (y - 34) * (y - 34) < 400 ? 0 : 255; }},
      {"checkerboard", [](int x, int y) { return (x + y) % 2 ? 255 : 0; }},
      {"stripes", [](int x, int) { return x % 4 < 2 ? 0 : 255; }},
  };
  for (const auto& [name, grey] : not_curds) {
    const FittedRecipe f = fit(name, grey);
    ASSERT_EQ(f.warnings.size(), 1u) << name;
    EXPECT_NE(f.warnings[0].find("no curd at these stages explains"), std::string::npos)
        << name << ": " << f.warnings[0];
    EXPECT_NE(f.warnings[0].find("at stage "), std::string::npos) << f.warnings[0];
    EXPECT_NE(f.toml.find("# WARNING: no curd"), std::string::npos) << name;
  }
  EXPECT_NE(fit("checkerboard", not_curds[2].second).warnings[0].find("more evenly"),
            std::string::npos);
  EXPECT_NE(fit("disk", not_curds[1].second).warnings[0].find("more unevenly"), std::string::npos);
  const FittedRecipe dot = fit("dot", [](int x, int y) { return x == 9 && y == 50 ? 0 : 255; });
  ASSERT_EQ(dot.warnings.size(), 1u);
  EXPECT_NE(dot.warnings[0].find("too few cells"), std::string::npos) << dot.warnings[0];
  for (const uint8_t grey : {uint8_t{255}, uint8_t{0}}) {
    try {
      fit(grey ? "white" : "black", [grey](int, int) { return grey; });
      ADD_FAILURE() << "a blank picture was fitted";
    } catch (const InputError& e) {
      EXPECT_NE(e.message().find("one shade in every pixel"), std::string::npos)
          << int{grey} << ": " << e.what();
    }
  }
  // A curd made by the engine passes.
  Design d;
  d.lattice = Lattice{2, 2, 6, Mode::canonical};
  d.curds = {CurdSpec{"c", std::vector<Probability>(6, *Probability::parse("0.75"))}};
  d.field = Box{{0, 0, 0}, {64, 64, 1}};
  const CurdField field = curdle(d, 3, d.field);
  const FittedRecipe curd = fit("curd", [&](int x, int y) {
    return field.value_at(Coord{x, 63 - y, 0}) ? 0 : 255;  // rows from the top
  });
  EXPECT_TRUE(curd.warnings.empty()) << curd.warnings[0];
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curdle::app
