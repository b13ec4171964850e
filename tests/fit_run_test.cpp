// Tests of fit_run.h: probabilities as recipes write them, options checked first, and a fitted
// recipe written whole.
#include "app/fit_run.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "curdle/error.h"
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

}  // namespace
}  // namespace curdle::app
