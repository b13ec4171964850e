// The STEP physical file writer: strings 7-bit whatever their script, reals always with a
// point, GlobalIds of IFC's alphabet derived from their key alone, and entities numbered as
// they are written.
#include "export/ifc/step_file.h"

#include <fmt/compile.h>
#include <gtest/gtest.h>

#include <set>
#include <sstream>

namespace curdle {
namespace {

TEST(StepFile, StringsAreSevenBitWithQuotesAndBackslashesDoubled) {
  EXPECT_EQ(step_string("Basalt slab 600 x 300"), "'Basalt slab 600 x 300'");
  EXPECT_EQ(step_string("O'Hare \\ yard"), "'O''Hare \\\\ yard'");
  EXPECT_EQ(step_string("O'Hare"), "'O''Hare'");
  EXPECT_EQ(step_string("C:\\yard"), "'C:\\\\yard'");
  EXPECT_EQ(step_string("Grès cérame"), "'Gr\\X2\\00E8\\X0\\s c\\X2\\00E9\\X0\\rame'");
  EXPECT_EQ(step_string("瓦"), "'\\X2\\74E6\\X0\\'");
  EXPECT_EQ(step_string("\xF0\x9F\x8C\xB3"), "'\\X4\\0001F333\\X0\\'");  // U+1F333, a tree
}

TEST(StepFile, RealsAlwaysHaveAPointAndRoundTrip) {
  EXPECT_EQ(step_real(0), "0.");
  EXPECT_EQ(step_real(600), "600.");
  EXPECT_EQ(step_real(-552.5), "-552.5");
  EXPECT_EQ(step_real(1e-5), "1.E-05");
  EXPECT_EQ(step_real(2.5e20), "2.5E20");
  EXPECT_EQ(std::stod(step_real(0.1 + 0.2)), 0.1 + 0.2);
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(step_real(std::numeric_limits<double>::quiet_NaN()),
               "check failed: std::isfinite\\(v\\): a STEP real must be finite");
}

TEST(StepFile, GlobalIdsAreIfcsBase64DerivedFromTheirKeyAlone) {
  const std::string digits = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_$";
  std::set<std::string> seen;
  for (int i = 0; i < 20000; ++i) {
    const std::string g = ifc_guid("recipe/7/P-R00-C" + std::to_string(i));
    ASSERT_EQ(g.size(), 22u);
    EXPECT_LE(digits.find(g[0]), 3u) << g;  // the first digit holds two bits
    EXPECT_EQ(g.find_first_not_of(digits), std::string::npos) << g;
    seen.insert(g);
  }
  EXPECT_EQ(seen.size(), 20000u);
  EXPECT_EQ(ifc_guid("a"), ifc_guid("a"));
  EXPECT_NE(ifc_guid("a"), ifc_guid("b"));
}

TEST(StepFile, AGuidSourceGivesTheGuidsOfItsPrefixAndWhatFollows) {
  const IfcGuidSource source("recipe/7/");
  for (const std::string id : {"", "P-R00-C1", "pset P-R00-C1", "Gr\xC3\xA8s"}) {
    const std::array<char, 22> g = source.guid("pset ", id);
    EXPECT_EQ(std::string(g.begin(), g.end()), ifc_guid("recipe/7/pset " + id));
  }
}

TEST(StepFile, EntitiesAreFormattedInPlaceAsTheirStringsWouldBe) {
  std::ostringstream out;
  StepWriter w(out, "layout.ifc", "IFC4", "ReferenceView_V1.2");
  const std::array<char, 22> guid = IfcGuidSource("k").guid("x");
  EXPECT_EQ(w.add(FMT_COMPILE("IFCPROPERTYSINGLEVALUE({},$,IFCLABEL({}),$)"), StepText{"O'Hare"},
                  StepText{"Gr\xC3\xA8s"}),
            1);
  EXPECT_EQ(w.add(FMT_COMPILE("IFCCARTESIANPOINT(({},{}))"), StepReal{600}, StepReal{1e-5}), 2);
  EXPECT_EQ(w.add(FMT_COMPILE("IFCWALL({},{})"), StepRoot{guid, 12}, StepRef{2}), 3);
  w.finish();
  const std::string s = out.str();
  EXPECT_NE(s.find("#1=IFCPROPERTYSINGLEVALUE('O''Hare',$,IFCLABEL('Gr\\X2\\00E8\\X0\\s'),$);\n"),
            std::string::npos);
  EXPECT_NE(s.find("#2=IFCCARTESIANPOINT((600.,1.E-05));\n"), std::string::npos);
  EXPECT_NE(s.find("#3=IFCWALL('" + ifc_guid("kx") + "',#12,#2);\n"), std::string::npos);
}

TEST(StepFile, EntitiesAreNumberedAsTheyAreWrittenBetweenHeaderAndEnd) {
  std::ostringstream out;
  StepWriter w(out, "layout.ifc", "IFC4", "ReferenceView_V1.2");
  EXPECT_EQ(w.add("IFCCARTESIANPOINT((0.,0.,0.))"), 1);
  EXPECT_EQ(w.add("IFCDIRECTION((0.,0.,1.))"), 2);
  w.finish();
  const std::string s = out.str();
  EXPECT_EQ(s.rfind("ISO-10303-21;\nHEADER;\n", 0), 0u);
  EXPECT_NE(s.find("FILE_SCHEMA(('IFC4'));"), std::string::npos);
  EXPECT_NE(s.find("DATA;\n#1=IFCCARTESIANPOINT((0.,0.,0.));\n#2=IFCDIRECTION((0.,0.,1.));\n"),
            std::string::npos);
  EXPECT_TRUE(s.ends_with("\nENDSEC;\nEND-ISO-10303-21;\n"));
  EXPECT_EQ(w.count(), 2);
}

}  // namespace
}  // namespace curdle
