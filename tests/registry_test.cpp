// Tests of registry.h.
#include "kinds/registry.h"

#include <gtest/gtest.h>

#include "layout_kind_support.h"

namespace curdle {
TEST(LayoutKind, TheRegistryNamesEveryKindAndRefusesASecondOfOneName) {
  for (const char* name : {"tile", "paving", "facade", "perforation", "park", "rhythm", "blocks"}) {
    const LayoutKind* k = find_layout_kind(name);
    ASSERT_NE(k, nullptr) << name;
    EXPECT_EQ(k->name(), name);
    EXPECT_FALSE(k->element_noun().empty());
    EXPECT_FALSE(k->keys().empty()) << name;
  }
  EXPECT_EQ(find_layout_kind("façade"), find_layout_kind("facade"));
  EXPECT_EQ(find_layout_kind("lawn"), nullptr);
  struct Another : SteppingStones {
    std::string_view name() const override { return "tile"; }
  };
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(register_layout_kind(std::make_unique<Another>()),
               "check failed: .*layout kind \"tile\" is registered twice");
  // An unknown kind's message lists the registered ones.
  try {
    run_of(kStones, {"layout.kind=\"lawn\""});
    FAIL() << "an unknown kind was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"tile\", \"paving\", \"facade\""), std::string::npos)
        << e.what();
  }
}

}  // namespace curdle
