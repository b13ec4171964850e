// Tests of page.h: what the page is told of a run — the layout's element and surface, a
// segment's values, the colour blend — and the cells a request may generate.
#include "app/page.h"

#include <gtest/gtest.h>

#include "curdle/error.h"
#include "test_support.h"

namespace curdle::app {
namespace {

const char* kPaving = R"(name = "yard"
[lattice]
base = 2
dimension = 2
[[curds]]
name = "dark"
probabilities = ["3/4", "2/3"]
[layout]
kind = "paving"
floor = [1200, 900]
tile = [300, 300]
[[layout.zones]]
name = "drain"
rect = [0, 0, 300, 300]
rule = "exclude"
)";

TEST(Page, TheRunDescribedItsSegmentAndTheColours) {
  const app::Run run = test::run_recipe("yard.toml", kPaving);
  const auto j = describe_run(run);
  EXPECT_EQ(j["name"], "yard");
  EXPECT_EQ(j["layout"]["element"], "paving tile");
  EXPECT_EQ(j["layout"]["segment_cells"], nlohmann::ordered_json({4, 3}));
  ASSERT_EQ(j["layout"]["surface"]["zones"].size(), 1u);
  EXPECT_EQ(j["layout"]["surface"]["zones"][0]["name"], "drain");
  EXPECT_EQ(j["downloads"].back(), "recipe.toml");
  const auto segment = segment_json(run, run.view, true);
  EXPECT_EQ(segment["value_bytes"], 1);
  EXPECT_EQ(segment["values"].get<std::string>().size(), 16u);  // 12 bytes in base64
  EXPECT_EQ(segment["report"]["curds"][0]["name"], "dark");
  EXPECT_EQ(value_colours_json({"#c80000", "#0000c8"})["values"][3], "#640064");
  EXPECT_THROW(value_colours_json({}), InputError);
  EXPECT_THROW(value_colours_json({"red"}), InputError);
  EXPECT_THROW(check_cells(run.recipe.design, run.view, 5, "this request would generate"),
               ResourceLimitError);
  EXPECT_NO_THROW(check_cells(run.recipe.design, run.view, 16, "this request would generate"));
}

}  // namespace
}  // namespace curdle::app
