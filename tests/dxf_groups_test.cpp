#include "site/dxf_groups.h"

#include <gtest/gtest.h>

#include "site/drawing.h"

namespace curdle::site {
namespace {

std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(read)";
}

TEST(DxfGroupsTest, GroupsComeWithTheirLines) {
  DxfGroups groups("  0\r\nSECTION\r\n  2\r\nENTITIES\r\n", "a.dxf");
  DxfGroup g;
  ASSERT_TRUE(groups.next(g));
  EXPECT_EQ(g.code, 0);
  EXPECT_EQ(g.value, "SECTION");
  EXPECT_EQ(g.line, 2u);
  ASSERT_TRUE(groups.next(g));
  EXPECT_EQ(g.value, "ENTITIES");
  groups.put_back(g);
  ASSERT_TRUE(groups.next(g));
  EXPECT_EQ(g.line, 4u);
  EXPECT_FALSE(groups.next(g));
}

TEST(DxfGroupsTest, NumbersAreOneNumberInTheCLocale) {
  DxfGroups groups("", "a.dxf");
  auto real = [&](std::string_view v) { return groups.real({10, v, 7}, "LINE 2A"); };
  EXPECT_EQ(real("1.5"), 1.5);
  EXPECT_EQ(real("-2.5E+03"), -2500);
  EXPECT_EQ(real("+3"), 3);
  for (const char* bad : {"1,5", "1 2", "", "nan", "inf", "1e999", "0x10", "1.#QNAN"}) {
    const std::string m = refusal([&] { real(bad); });
    EXPECT_NE(m.find("a.dxf: line 7: the LINE 2A has"), std::string::npos) << bad << ": " << m;
  }
  EXPECT_EQ(groups.integer({70, "6", 3}, "header"), 6);
  EXPECT_NE(refusal([&] {
              groups.integer({70, "6.0", 3}, "header");
            }).find("one whole number"),
            std::string::npos);
}

TEST(DxfGroupsTest, DamagedLinesAreNamed) {
  DxfGroup g;
  DxfGroups code("0\nSECTION\nX1\nfoo\n", "a.dxf");
  code.next(g);
  EXPECT_NE(refusal([&] { code.next(g); }).find("line 3 should be a group code"),
            std::string::npos);
  DxfGroups cut("0\nSECTION\n2", "a.dxf");
  cut.next(g);
  EXPECT_NE(refusal([&] { cut.next(g); }).find("without its value"), std::string::npos);
  const std::string long_text = "999\n" + std::string(kLongestDxfLine + 1, 'x') + "\n";
  DxfGroups long_line(long_text, "a.dxf");  // holds a view of the bytes: they outlive it
  EXPECT_NE(refusal([&] { long_line.next(g); }).find("line 2 is 65537 characters long"),
            std::string::npos);
}

}  // namespace
}  // namespace curdle::site
