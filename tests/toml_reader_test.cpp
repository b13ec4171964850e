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

namespace curdle {

// Names are one line of text that shows as it reads: line breaks, bidirectional controls,
// invisible characters and non-characters are refused where they are read, naming the key.
TEST(Recipe, NamesThatWouldNotShowAsTheyReadAreRefused) {
  const std::string head = "[lattice]\nbase = 2\ndimension = 2\n";
  const std::string curd = "[[curds]]\nprobabilities = [\"3/4\"]\n";
  const std::string layout = "[layout]\nkind = \"paving\"\nfloor = [900, 600]\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"name = \"yard\\n0\\nLAYER\"\n" + head + curd, "key 'name'"},
      {head + "[[curds]]\nname = \"a\\u202Eb\"\nprobabilities = [\"3/4\"]\n", "curds.0.name"},
      {head + curd + layout + "materials = [\"stone\", \"brick\\u200B\"]\n", "layout.materials.1"},
      {head + curd + layout + "materials = [\"stone\", \"end\\uFFFF\"]\n", "layout.materials.1"},
      {head + curd + layout +
           "[[layout.zones]]\nname = \"pit\\u2066\"\nrect = [0, 0, 300, 300]\nrule = \"exclude\"\n",
       "layout.zones.0.name"},
      {"description = \"a \\u202Elie\"\n" + head + curd, "key 'description'"},
  };
  for (const auto& [text, key] : cases) {
    try {
      parse_recipe(text, "r.toml");
      ADD_FAILURE() << "accepted:\n" << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
  // A description may run over lines; Unicode letters are welcome everywhere.
  EXPECT_NO_THROW(parse_recipe("name = \"Grès\"\ndescription = \"two\\nlines\"\n" + head + curd +
                                   layout + "materials = [\"pierre\", \"grès cérame\"]\n",
                               "r.toml"));
}

// A key deeper than toml++'s stack can take is refused from the text, naming its line; dots in
// strings and comments are text.
TEST(Recipe, KeysDeeperThanSixtyFourPartsAreRefusedBeforeParsing) {
  EXPECT_EQ(reading::deepest_key("a.b.c = 1\n[x.y]\n").parts, 3);
  EXPECT_EQ(reading::deepest_key("a = \"1.2.3.4.5\" # 6.7.8.9\nb = '''x.y.z'''\n").parts, 1);
  EXPECT_EQ(reading::deepest_key("a = [1.5, 2.5]\n").parts, 2);
  std::string deep = "a";
  for (int i = 0; i < 60000; ++i) deep += ".a";
  for (const std::string& text :
       {deep + " = 1\n", "[" + deep + "]\n", "x = {" + deep + " = 1}\n"}) {
    const std::string e = error_of(std::string(kGood) + text);
    EXPECT_NE(e.find("has 60001 parts; at most 64"), std::string::npos) << e.substr(0, 200);
  }
  // 64 parts are read (and refused as an unknown key, not for their depth).
  EXPECT_EQ(error_of(std::string(kGood) + "[" + deep.substr(0, 127) + "]\n").find("parts"),
            std::string::npos);
}

}  // namespace curdle
