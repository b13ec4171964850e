// Optional modules are found where a build tree or an installation puts them, and a missing
// one is named with the places looked in.
#include "io/module_loader.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {

TEST(ModuleLoader, FindsTheImageModuleAndNamesWhereAMissingOneWasLookedFor) {
  std::string failure;
  EXPECT_NE(load_curdle_module(CURDLE_IMAGE_MODULE_NAME_FOR_TESTS, &failure), nullptr) << failure;
  EXPECT_EQ(load_curdle_module("libcurdle_nothing.so", &failure), nullptr);
  EXPECT_NE(failure.find("libcurdle_nothing.so is not installed (looked in "), std::string::npos)
      << failure;
}

}  // namespace
}  // namespace curdle
