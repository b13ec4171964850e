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

namespace curdle::app {

TEST(Run, SizesAreWholeBytesOfAtLeastAKilobyte) {
  EXPECT_EQ(parse_bytes("8G", "max_memory"), uint64_t{8} << 30);
  EXPECT_EQ(parse_bytes("1.5K", "max_memory"), 1536u);
  // 0.1 bytes read as 0, which means "the default": a limit that was no limit.
  for (const char* bad : {"0.1", "1", "1023", "0", "-1G", "lots", "1e400", "", "5Q"})
    EXPECT_THROW(parse_bytes(bad, "max_memory"), InputError) << bad;
}

}  // namespace curdle::app
