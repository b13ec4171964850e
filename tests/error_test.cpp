// Tests of error.h: a message names the file, line and key, or the run parameter as the shell
// spells it.
#include "curdle/error.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {

TEST(Error, MessagesNameWhereTheInputWasWrong) {
  const InputError located(SourceLocation{"r.toml", 4, 7, "lattice.base", ""}, "must be 2 to 64");
  EXPECT_STREQ(located.what(), "r.toml:4:7: key 'lattice.base': must be 2 to 64");
  EXPECT_EQ(located.message(), "must be 2 to 64");
  const InputError window(parameter("window"), "must lie inside the field");
  EXPECT_EQ(render_error(window, [](const std::string& p) { return "--" + p; }),
            "--window: must lie inside the field");
  // An override names its recipe key after the parameter.
  const InputError set(parameter("set", "lattice.base"), "must be 2 to 64");
  EXPECT_EQ(render_error(set, [](const std::string&) { return std::string("--set"); }),
            "--set lattice.base: must be 2 to 64");
  const InputError plain("no layout");
  EXPECT_STREQ(plain.what(), "no layout");
  const ResourceLimitError limit(parameter("max_memory"), "above the limit");
  EXPECT_NE(dynamic_cast<const InputError*>(&limit), nullptr);  // exit 2 as any bad input
}

}  // namespace
}  // namespace curdle
