// Tests of run.h.
#include "app/run.h"

#include <gtest/gtest.h>

#include "outputs_support.h"

namespace fs = std::filesystem;

namespace curdle::app {
TEST(Outputs, SeedsAndWindowsAreCheckedAsParameters) {
  RunRequest request;
  request.recipe_text = kTiles;
  request.recipe_path = "tiles.toml";
  request.seed = "18446744073709551616";
  try {
    resolve_run(request);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().parameter, "seed");
    EXPECT_EQ(render_error(e, [](const std::string& p) { return "--" + p; }).rfind("--seed: ", 0),
              0u);
  }
  request.seed = "";
  request.window = "1,2,3";
  try {
    resolve_run(request);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().parameter, "window");
  }
}

}  // namespace curdle::app
