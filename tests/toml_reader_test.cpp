// Tests of toml_reader.h.
#include "recipe/toml_reader.h"

#include <gtest/gtest.h>

#include "recipe_support.h"

namespace curdle {
TEST(Recipe, ErrorsNameTheLineTheKeyAndWhatIsAllowed) {
  std::string e = error_of(std::string(kGood) + "colour = 3\n");
  EXPECT_NE(e.find("r.toml:16:10"), std::string::npos) << e;
  EXPECT_NE(e.find("curds.1.colour"), std::string::npos) << e;
  EXPECT_NE(e.find("#rrggbb"), std::string::npos) << e;

  e = error_of(R"([lattice]
base = 4
dimenson = 2
[[curds]]
probabilities = ["1/2"]
)");
  EXPECT_NE(e.find("r.toml:3:1"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'dimension'"), std::string::npos) << e;

  e = error_of(R"([lattice]
base = 4
dimension = 2
[[curds]]
probabilities = ["4/3"]
)");
  EXPECT_NE(e.find("curds.0.probabilities.0"), std::string::npos) << e;
  EXPECT_NE(e.find("from 0 to 1"), std::string::npos) << e;
}

}  // namespace curdle
