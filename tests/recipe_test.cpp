#include "recipe/recipe.h"

#include <gtest/gtest.h>

#include "curdle/error.h"
#include "layout/builder.h"

namespace curdle {
namespace {

const char* kGood = R"(name = "t"
seed = 9
[lattice]
base = 4
dimension = 2
mode = "canonical"
[field]
cells = [67, 67]
[[curds]]
name = "red"
probabilities = ["3/4", "2/3"]
colour = "#c0392b"
[[curds]]
name = "blue"
probabilities = [0.75, "0.5"]
)";

std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parse_recipe(text, "r.toml", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// kGood's lattice with one curd of two stages, and a [layout] of `keys`.
std::string with_layout(const std::string& keys) {
  return std::string(kGood).substr(0, std::string(kGood).find("[field]")) +
         "[[curds]]\nprobabilities = [\"1/2\", \"1/2\"]\n[layout]\n" + keys;
}

}  // namespace

TEST(Recipe, ReadsEveryKey) {
  const Recipe r = parse_recipe(kGood, "r.toml");
  EXPECT_EQ(r.design.name, "t");
  EXPECT_EQ(r.seed, 9u);
  EXPECT_EQ(r.design.lattice.base, 4);
  EXPECT_EQ(r.design.lattice.stages, 2);
  EXPECT_EQ(r.design.field.size[0], 67);
  ASSERT_EQ(r.design.curds.size(), 2u);
  EXPECT_EQ(r.design.curds[1].probabilities[0].text(), "0.75");
  EXPECT_EQ((r.design.curds[0].colour), (Rgb{0xc0, 0x39, 0x2b}));
}

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

TEST(Recipe, ExactModeNeedsWholeCounts) {
  const std::string e = error_of(kGood, {"lattice.mode=exact"});
  EXPECT_NE(e.find("curds.0.probabilities.1"), std::string::npos) << e;
  EXPECT_NE(e.find("not a whole number"), std::string::npos) << e;
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

TEST(Recipe, Windows) {
  const Recipe r = parse_recipe(kGood, "r.toml");
  const Box w = parse_window("3,4,10,20", r.design);
  EXPECT_EQ(w.origin[0], 3);
  EXPECT_EQ(w.size[1], 20);
  EXPECT_THROW(parse_window("60,0,10,10", r.design), InputError);
  EXPECT_THROW(parse_window("1,2,3", r.design), InputError);
  EXPECT_THROW(parse_window("a,b,c,d", r.design), InputError);
}

// layout.bond and layout.origin = "centre": read as written, and refused clearly where they
// cannot hold.
TEST(Recipe, BondAndCentredOrigin) {
  const std::string wall =
      with_layout("kind = \"facade\"\npanel = [215, 65]\njoint = 10\nwall = [4000, 2000]\n");
  Recipe r = parse_recipe(wall + "bond = \"half\"\norigin = \"centre\"\n", "r.toml");
  EXPECT_DOUBLE_EQ(r.layout->bond, 0.5);
  EXPECT_TRUE(r.layout->centred);
  EXPECT_NEAR(r.layout->shift[0], centring_shift(4000, 215, 10), 1e-9);
  EXPECT_GT(r.layout->shift[0], 0);
  EXPECT_DOUBLE_EQ(parse_recipe(wall + "bond = \"third\"\n", "r.toml").layout->bond, 1.0 / 3);
  EXPECT_DOUBLE_EQ(parse_recipe(wall + "bond = \"quarter\"\n", "r.toml").layout->bond, 0.25);
  std::string e = error_of(wall + "bond = \"flemish\"\n");
  EXPECT_NE(e.find("layout.bond"), std::string::npos) << e;
  EXPECT_NE(e.find("\"stack\""), std::string::npos) << e;
  e = error_of(wall + "origin = \"centre\"\nshift = [10, 10]\n");
  EXPECT_NE(e.find("layout.shift"), std::string::npos) << e;
  e = error_of(wall + "bond = \"half\"\ncombine = \"keep\"\n");
  EXPECT_NE(e.find("mix"), std::string::npos) << e;
  e = error_of(wall + "origin = \"middle\"\n");
  EXPECT_NE(e.find("\"centre\""), std::string::npos) << e;
}

// [[layout.zones]]: read in millimetres; every way to get one wrong is named.
TEST(Recipe, Zones) {
  const std::string floor =
      with_layout("kind = \"paving\"\ntile = [600, 300]\nfloor = [12000, 8000]\n");
  const std::string planter = "[[layout.zones]]\nname = \"planter\"\nrule = \"exclude\"\n";
  Recipe r = parse_recipe(floor + planter + "rect = [7000, 3000, 2000, 3000]\n" +
                              "[[layout.zones]]\nname = \"band\"\nrule = \"value\"\nvalue = 1\n"
                              "polygon = [[0, 0], [12000, 0], [6000, 900]]\n",
                          "r.toml");
  ASSERT_EQ(r.layout->zones.size(), 2u);
  EXPECT_EQ(r.layout->zones[0].rects.size(), 1u);
  EXPECT_EQ(r.layout->zones[1].rule, ZoneRule::value);
  EXPECT_EQ(r.layout->zones[1].value, 1u);
  const std::vector<std::pair<std::string, std::string>> wrong = {
      {planter + "rect = [7000, 3000, 9000, 3000]\n", "outside the surface"},
      {planter + "polygon = [[0, 0], [1000, 1000], [1000, 0], [0, 1000]]\n", "simple polygon"},
      {planter + "rect = [0, 0, nan, 10]\n", "layout.zones.0.rect"},
      {planter, "either rect"},
      {"[[layout.zones]]\nname = \"x\"\nrule = \"value\"\nvalue = 9\nrect = [0, 0, 10, 10]\n",
       "layout.zones.0.value"},
      {"[[layout.zones]]\nname = \"x\"\nrule = \"hide\"\nrect = [0, 0, 10, 10]\n", "\"exclude\""},
  };
  for (const auto& [zone, said] : wrong) {
    const std::string e = error_of(floor + zone);
    EXPECT_NE(e.find(said), std::string::npos) << zone << "\n" << e;
  }
}

// layout.outline stands for the floor's size, and is refused where it cannot be cut.
TEST(Recipe, Outline) {
  const std::string head = with_layout("kind = \"paving\"\ntile = [600, 300]\n");
  const Recipe r = parse_recipe(
      head +
          "outline = [[0, 0], [12000, 0], [12000, 5000], [8000, 5000], [8000, 8000], [0, 8000]]\n",
      "r.toml");
  ASSERT_TRUE(r.layout->size);
  EXPECT_EQ(*r.layout->size, (std::array<double, 2>{12000, 8000}));
  EXPECT_EQ(r.layout->outline.size(), 6u);
  // Sloping and curved edges are cut along (a triangle here), but not in keep mode.
  EXPECT_EQ(parse_recipe(head + "outline = [[0, 0], [1000, 0], [500, 900]]\n", "r.toml")
                .layout->outline.size(),
            3u);
  EXPECT_NE(error_of(head + "combine = \"keep\"\noutline = [[0, 0], [1000, 0], [500, 900]]\n")
                .find("combine = \"mix\""),
            std::string::npos);
  const std::vector<std::pair<std::string, std::string>> wrong = {
      {"outline = [[-10, 0], [1000, 0], [1000, 900], [-10, 900]]\n", "from 0"},
      {"floor = [500, 500]\noutline = [[0, 0], [1000, 0], [1000, 900], [0, 900]]\n",
       "outside the surface"},
      {"outline = [[0, 0], [1000, 0]]\n", "at least 3 corners"},
  };
  for (const auto& [text, said] : wrong) {
    const std::string e = error_of(head + text);
    EXPECT_NE(e.find("layout.outline"), std::string::npos) << text << "\n" << e;
    EXPECT_NE(e.find(said), std::string::npos) << text << "\n" << e;
  }
  const std::string e = error_of(head);  // neither a floor nor an outline
  EXPECT_NE(e.find("layout.floor"), std::string::npos) << e;
}

}  // namespace curdle
