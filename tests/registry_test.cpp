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

// What the writers and the page once asked of a kind's name, each kind now answers: whether
// its pieces are outside, which outputs only it writes, and the building it was laid round.
TEST(LayoutKind, EachKindSaysWhatItIsInsteadOfItsNameBeingAsked) {
  for (const char* name : {"facade", "perforation", "rhythm", "paving", "park"})
    EXPECT_TRUE(layout_kind(name).outdoors()) << name;
  for (const char* name : {"tile", "blocks"}) EXPECT_FALSE(layout_kind(name).outdoors()) << name;
  EXPECT_TRUE(layout_kind("park").owns_output("planting.csv"));
  EXPECT_TRUE(layout_kind("park").owns_output("surfaces.csv"));
  EXPECT_TRUE(layout_kind("perforation").owns_output("punching.csv"));
  EXPECT_FALSE(layout_kind("perforation").owns_output("planting.csv"));
  for (const LayoutKind* k : layout_kinds())
    EXPECT_FALSE(k->owns_output("layout.glb")) << k->name();
  LayoutSpec spec;
  spec.set_kind(layout_kind("facade"));
  EXPECT_EQ(spec.kind->envelope(spec), nullptr) << "a wall of its own, not a building";
}

}  // namespace curdle
