// Tests of reproduce.h.
#include "app/reproduce.h"

#include <gtest/gtest.h>

#include "outputs_support.h"

namespace fs = std::filesystem;

namespace curdle::app {
TEST(Outputs, TheReproducingRecipeNeedsNoOptions) {
  RunRequest request;
  request.recipe_text = kTiles;
  request.recipe_path = "tiles.toml";
  request.overrides = {"curds.0.probabilities=[\"1/2\",\"1/2\"]"};
  request.seed = "99";
  request.window = "2,2,4,4";
  const app::Run run = resolve_run(request);
  RunRequest again;
  again.recipe_text = reproducing_recipe(run);
  again.recipe_path = "again.toml";
  const app::Run back = resolve_run(again);
  EXPECT_EQ(back.seed, 99u);
  EXPECT_EQ(back.view, run.view);
  EXPECT_EQ(back.recipe.design.curds[0].probabilities[0].text(), "1/2");
  EXPECT_EQ(generate_command(run),
            "curdle generate tiles.toml --set 'curds.0.probabilities=[\"1/2\",\"1/2\"]' --seed 99 "
            "--window 2,2,4,4");
}

TEST(Outputs, TheReproducingRecipeKeepsEverySeed) {
  for (const char* seed :
       {"0", "9223372036854775807", "9223372036854775808", "18446744073709551615"}) {
    RunRequest request;
    request.recipe_text = kTiles;
    request.recipe_path = "tiles.toml";
    request.seed = seed;
    const app::Run run = resolve_run(request);
    RunRequest again;
    again.recipe_text = reproducing_recipe(run);
    again.recipe_path = "again.toml";
    EXPECT_EQ(std::to_string(resolve_run(again).seed), seed);
    RunRequest set;  // a recipe's seed set as --set seed=N or seed = "N"
    set.recipe_text = kTiles;
    set.recipe_path = "tiles.toml";
    set.overrides = {std::string("seed=") + seed};
    EXPECT_EQ(std::to_string(resolve_run(set).seed), seed);
    set.overrides = {std::string("seed=\"") + seed + "\""};
    EXPECT_EQ(std::to_string(resolve_run(set).seed), seed);
  }
  for (const char* bad :
       {"-1", "18446744073709551616", "\"-1\"", "\"+5\"", "\"\"", "\"1e3\"", "2.5", "\" 7\""}) {
    RunRequest request;
    request.recipe_text = kTiles;
    request.recipe_path = "tiles.toml";
    request.overrides = {std::string("seed=") + bad};
    EXPECT_THROW(resolve_run(request), InputError) << bad;
  }
}

}  // namespace curdle::app
