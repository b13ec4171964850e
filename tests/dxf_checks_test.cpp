#include "site/dxf_checks.h"

#include <gtest/gtest.h>

#include "site/drawing.h"

namespace curdle::site {
namespace {

std::string checks_refusal(const std::string& bytes) {
  try {
    check_dxf_bytes(bytes, "site.dxf");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(DxfChecksTest, CountsMustFitTheFile) {
  const std::string head = "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nA\n90\n";
  EXPECT_EQ(checks_refusal(head + "3\n70\n1\n0\nENDSEC\n0\nEOF\n"), "(accepted)");
  const std::string m = checks_refusal(head + "99999999\n70\n1\n0\nENDSEC\n0\nEOF\n");
  EXPECT_NE(m.find("the LWPOLYLINE at line 10 says it has 99999999 parts"), std::string::npos) << m;
  // dxflib reads a group code that is no number as 0, so an entity can begin there.
  EXPECT_NE(
      checks_refusal("0\nSECTION\n2\nENTITIES\n\xd0\nLWPOLYLINE\n90\n99999999\n").find("parts"),
      std::string::npos);
  EXPECT_NE(checks_refusal("0\nSECTION\n2\nENTITIES\n0\nSPLINE\n73\n-5\n").find("parts"),
            std::string::npos);
}

TEST(DxfChecksTest, OtherFilesAreNamed) {
  EXPECT_NE(checks_refusal("AutoCAD Binary DXF\r\n\x1a").find("binary DXF"), std::string::npos);
  EXPECT_NE(checks_refusal("AC1027xxxxxxxx").find("DWG"), std::string::npos);
  EXPECT_NE(checks_refusal("<svg/>").find("not a DXF"), std::string::npos);
  EXPECT_NE(checks_refusal(std::string("0\nSECTION\n") + '\0').find("NUL"), std::string::npos);
  // One long line that begins with 0 and holds SECTION: no group code alone on its line
  // (dxflib spun on it without end, found by fuzzing).
  EXPECT_NE(checks_refusal("0\xbf\xff??? SECTION ???").find("not a DXF"), std::string::npos);
  EXPECT_EQ(checks_refusal("  0\r\nSECTION\r\n2\r\nENTITIES\r\n0\r\nENDSEC\r\n0\r\nEOF\r\n"),
            "(accepted)");
}

}  // namespace
}  // namespace curdle::site
