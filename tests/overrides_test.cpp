// Tests of overrides.h.
#include "recipe/overrides.h"

#include <gtest/gtest.h>

#include "recipe/toml_reader.h"
#include "recipe_support.h"

namespace curdle {
TEST(Recipe, OverridesByDottedPath) {
  const Recipe r =
      parse_recipe(kGood, "r.toml",
                   {"lattice.mode=exact", "curds.0.probabilities=[\"1/2\",\"1/4\"]",
                    "curds.1.probabilities.1=1/4", "field.cells=[16,8]", "name=other"});
  EXPECT_EQ(r.design.lattice.mode, Mode::exact);
  EXPECT_EQ(r.design.curds[0].probabilities[1].text(), "1/4");
  EXPECT_EQ(r.design.curds[1].probabilities[1].text(), "1/4");
  EXPECT_EQ(r.design.field.size[1], 8);
  EXPECT_EQ(r.design.name, "other");
}

TEST(Recipe, OverrideErrorsNameTheOverride) {
  const std::string e = error_of(kGood, {"lattice.base=99"});
  EXPECT_NE(e.find("set lattice.base: must be"), std::string::npos) << e;
  EXPECT_NE(e.find("from 2 to 64"), std::string::npos) << e;
  // Each shell names the override its own way: the command line's option, the API's key.
  try {
    parse_recipe(kGood, "good.toml", {"lattice.base=99"});
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(render_error(error, [](const std::string& p) { return "--" + p; }),
              "--set lattice.base: must be a whole number from 2 to 64");
    EXPECT_EQ(render_error(error, [](const std::string&) { return std::string(); }),
              "key 'lattice.base': must be a whole number from 2 to 64");
  }
  EXPECT_NE(error_of(kGood, {"curds.5.name=x"}).find("out of range"), std::string::npos);
}

}  // namespace curdle

namespace curdle {

TEST(Recipe, AnArrayIndexIsAWholeNumberAndNothingElse) {
  for (const char* bad : {"curds.0.probabilities.0abc=\"1/2\"", "curds.0x.name=\"a\"",
                          "curds.0.probabilities.9=\"1/2\"", "curds.-1.name=\"a\""})
    EXPECT_THROW(parse_recipe(kGood, "r.toml", {bad}), InputError) << bad;
  EXPECT_NO_THROW(parse_recipe(kGood, "r.toml", {"curds.0.probabilities.0=\"1/2\""}));
}

}  // namespace curdle

namespace curdle {

// A request may choose a site drawing's layers, never a file: not by its key, nor inside an
// inline table or array it sets.
TEST(Overrides, NamesAFile) {
  EXPECT_TRUE(override_names_a_file("layout.mask=\"/etc/passwd\""));
  EXPECT_TRUE(override_names_a_file("layout.site.file=\"/etc/site.dxf\""));
  EXPECT_TRUE(override_names_a_file("curds.0.density.path=x.png"));
  EXPECT_TRUE(override_names_a_file("layout={kind=\"facade\",mask=\"/any/path\"}"));
  EXPECT_TRUE(override_names_a_file("layout.site={file=\"/etc/x.dxf\",outline=\"A\"}"));
  EXPECT_TRUE(
      override_names_a_file("curds=[{name=\"a\",density={kind=\"image\",path=\"/x.png\"}}]"));
  EXPECT_FALSE(override_names_a_file("layout.site.outline=\"A-OTLN\""));
  EXPECT_FALSE(override_names_a_file("layout.site.zones=[{layer=\"PIT\",rule=\"exclude\"}]"));
  EXPECT_FALSE(override_names_a_file("layout.tile=[300,300]"));
  EXPECT_FALSE(override_names_a_file("name=path"));  // a bare word is a value, not a key
}

// An override is one key and one value: a line break or quote in the key, or a second line in
// the value, cannot smuggle in another key.
TEST(Overrides, OneKeyAndOneValue) {
  toml::table doc = reading::parse_toml("name = \"x\"\nseed = 1\n", "r.toml");
  EXPECT_THROW(reading::apply_override(doc, "name=\"y\"\nseed = 5"), InputError);
  EXPECT_THROW(reading::apply_override(doc, "name\nseed=5"), InputError);
  EXPECT_THROW(reading::apply_override(doc, "\"name\"=5"), InputError);
  EXPECT_THROW(reading::apply_override(doc, "lattice..base=5"), InputError);
  EXPECT_EQ(doc["seed"].value<int64_t>(), 1);
  reading::apply_override(doc, "lattice.base=3");
  reading::apply_override(doc, "curds-2_b=3");
  EXPECT_EQ(doc["lattice"]["base"].value<int64_t>(), 3);
}

}  // namespace curdle
