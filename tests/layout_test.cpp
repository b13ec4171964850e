// Tests of layout.h: a kind's own keys, held and copied with the spec.
#include "layout/layout.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {
struct PierKeys : KindKeysOf<PierKeys> {
  double pitch = 600;
};
struct QuayKeys : KindKeysOf<QuayKeys> {};
}  // namespace

TEST(OwnKeys, AKindsKeysAreFoundAsThemselvesAndCopiedWithTheirOwner) {
  OwnKeys keys(std::make_unique<PierKeys>());
  keys.as<PierKeys>().pitch = 450;
  EXPECT_EQ(keys.find<QuayKeys>(), nullptr);  // another kind's record is not there
  const OwnKeys copy = keys;
  keys.as<PierKeys>().pitch = 300;
  EXPECT_EQ(copy.as<PierKeys>().pitch, 450);  // a copy of its own, not the same record
  EXPECT_EQ(OwnKeys().find<PierKeys>(), nullptr);
}

}  // namespace curdle
