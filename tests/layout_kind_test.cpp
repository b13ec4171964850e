// Layout kinds are units: a kind defined here alone, registered with one line, gets every
// layout output from the same writers as the built-in kinds; the registry refuses what it must.
#include "layout/layout_kind.h"

#include <gtest/gtest.h>

#include "layout_kind_support.h"

namespace curdle {
namespace {

// The [layout] keys patterns/README.md documents, each with the kinds it names: the key table
// of "## Layouts" (its kinds column; "all" is every kind), the ordering table (every kind) and
// each kind's own section ("### Park (`kind = "park"`)").
std::map<std::string, std::set<std::string>> documented_layout_keys() {
  const std::vector<std::string> all = {"tile", "paving", "facade", "perforation",
                                        "park", "rhythm", "blocks"};
  std::ifstream in(std::string(CURDLE_SOURCE_DIR) + "/patterns/README.md");
  std::map<std::string, std::set<std::string>> keys;
  std::string line, section;
  bool kinds_column = false;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) section = line == "## Layouts" ? "all" : "";
    if (line.rfind("### ", 0) == 0) {
      const size_t q = line.find("kind = \"");
      section = q == std::string::npos ? "" : line.substr(q + 8, line.find('"', q + 8) - q - 8);
    }
    if (line.rfind("| key | kinds |", 0) == 0) kinds_column = true;
    if (line.rfind("| key | type |", 0) == 0) kinds_column = false;
    if (section.empty() || line.rfind("| `layout.", 0) != 0) continue;
    const std::string key = line.substr(10, line.find('`', 10) - 10);
    std::set<std::string>& kinds = keys[key];
    if (section != "all") {
      kinds.insert(section);
    } else if (!kinds_column) {  // the ordering table: every kind
      kinds.insert(all.begin(), all.end());
    } else {
      const size_t a = line.find('|', 3) + 1, b = line.find('|', a);
      std::string named = line.substr(a, b - a);
      if (named.find("all") != std::string::npos || named.find_first_not_of(' ') == named.npos)
        kinds.insert(all.begin(), all.end());
      for (const std::string& k : all)
        if (named.find(k) != std::string::npos) kinds.insert(k);
    }
  }
  return keys;
}

// The smallest recipe of each kind that reads.
std::string minimal_recipe(const std::string& kind) {
  const int dimension = kind == "rhythm" ? 1 : kind == "blocks" ? 3 : 2;
  std::string text =
      "name = \"keys\"\n[lattice]\nbase = 2\ndimension = " + std::to_string(dimension) +
      "\n[[curds]]\nname = \"c\"\nprobabilities = [\"3/4\", \"2/3\"]\n"
      "[layout]\nkind = \"" +
      kind + "\"\n";
  if (kind == "paving") text += "floor = [3000, 3000]\n";
  if (kind == "facade") text += "wall = [3000, 3000]\n";
  if (kind == "perforation")
    text += "sheet = [1200, 1200]\nthickness = 2\nholes = [{diameter = 100}]\n";
  if (kind == "park")
    text += "elements = [{type = \"tree\", form = \"object\", size = [200, 200]}]\n";
  if (kind == "rhythm") text += "widths = [0, 100]\n";
  return text;
}

}  // namespace

TEST(LayoutKind, AKindDefinedInATestGetsEveryLayoutOutput) {
  static const bool registered = [] {
    register_layout_kind(std::make_unique<SteppingStones>());  // the one line
    return true;
  }();
  ASSERT_TRUE(registered);
  const app::Run run = run_of(kStones, {"seed=3"});
  app::MemorySink sink;
  app::write_outputs(
      run,
      app::select_outputs(run, {"layout.svg", "schedule.csv", "layout.dxf", "layout.glb"}, nullptr),
      sink, 1, nullptr);
  const auto& files = sink.files();
  const std::string &svg = files.at("layout.svg"), &csv = files.at("schedule.csv"),
                    &dxf = files.at("layout.dxf"), &glb = files.at("layout.glb");

  // The schedule: one row per stone, each 450 mm square, of granite.
  std::set<std::string> ids;
  std::istringstream rows(csv);
  std::string row;
  std::getline(rows, row);  // header
  while (std::getline(rows, row)) {
    ids.insert(row.substr(0, row.find(',')));
    EXPECT_NE(row.find(",450,450,"), std::string::npos) << row;
    EXPECT_NE(row.find(",Granite,"), std::string::npos) << row;
  }
  ASSERT_GT(ids.size(), 5u);
  EXPECT_LT(ids.size(), 64u);  // no stone where no curd survived
  for (const std::string& id : ids) {
    EXPECT_EQ(id.rfind("S-", 0), 0u) << id;
    EXPECT_EQ(count(svg, "id=\"" + id + "\""), 1u) << id;  // drawn once, by its ID
    EXPECT_GE(count(dxf, "\n" + id + "\n"), 1u) << id;     // its label on the ID layer
  }
  EXPECT_NE(svg.find("class=\"stepping-stones\" data-element-type=\"stone\""), std::string::npos);
  EXPECT_NE(svg.find(std::to_string(ids.size()) + " stones"), std::string::npos);  // legend
  EXPECT_NE(dxf.find("$INSUNITS\n 70\n4\n"), std::string::npos);                   // millimetres
  EXPECT_GE(count(dxf, "\nGranite\n"), ids.size());  // every stone on its material's layer

  // The glTF: a node per stone, named by its ID, 40 mm thick (glTF is in metres).
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn,
                                          reinterpret_cast<const unsigned char*>(glb.data()),
                                          static_cast<unsigned>(glb.size())))
      << err;
  size_t named = 0;
  for (const tinygltf::Node& n : model.nodes)
    if (ids.count(n.name)) {
      ++named;
      ASSERT_EQ(n.scale.size(), 3u);
      EXPECT_NEAR(n.scale[0], 0.45, 1e-6);
      EXPECT_NEAR(n.scale[1], 0.04, 1e-6);
    }
  EXPECT_EQ(named, ids.size());
}

TEST(LayoutKind, AKeyTheKindDoesNotReadIsRefused) {
  // A kind that lists a key but never reads it: the key is refused, not silently ignored.
  struct Forgetful : SteppingStones {
    std::string_view name() const override { return "forgetful-stones"; }
    std::vector<std::string> keys() const override { return {"cell", "inset", "edging"}; }
  };
  static const bool registered = [] {
    register_layout_kind(std::make_unique<Forgetful>());
    return true;
  }();
  ASSERT_TRUE(registered);
  // Even when the recipe leaves it out: the reader must ask for every key its kind lists.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(run_of(kStones, {"layout.kind=\"forgetful-stones\""}),
               "check failed: .*the forgetful-stones kind lists keys its reader never asks for");
  try {
    run_of(kStones, {"layout.kind=\"forgetful-stones\"", "layout.edging=\"steel\""});
    FAIL() << "layout.edging was accepted and never read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'edging' is not read by a forgetful-stones layout"),
              std::string::npos)
        << e.what();
  }

  // highlight outlines a window of a surface's cells: a line of bays does not read it.
  const std::string rhythm = R"(name = "fins"
[lattice]
base = 2
dimension = 1
[[curds]]
name = "fin"
probabilities = ["3/4", "2/3"]
[layout]
kind = "rhythm"
widths = [0, 100]
highlight = [0, 0, 2, 1]
)";
  try {
    run_of(rhythm);
    FAIL() << "layout.highlight was accepted on a rhythm";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("highlight"), std::string::npos) << e.what();
  }
}

TEST(LayoutKind, TheReadmesKeyTableIsWhatEachKindReads) {
  const auto documented = documented_layout_keys();
  ASSERT_GT(documented.size(), 40u);
  for (const char* kind : {"tile", "paving", "facade", "perforation", "park", "rhythm", "blocks"}) {
    ASSERT_NO_THROW(run_of(minimal_recipe(kind))) << kind;
    for (const auto& [key, kinds] : documented) {
      if (key == "kind") continue;
      // A value no key takes: a key the kind reads is refused for its value, any other as
      // unknown.
      std::string message = "(accepted)";
      try {
        run_of(minimal_recipe(kind), {"layout." + key + "=[\"?\"]"});
      } catch (const InputError& e) {
        message = e.what();
      }
      const bool refused_as_unknown =
          message.find("unknown key '" + key + "'") != std::string::npos ||
          message.find("'" + key + "' is not read") != std::string::npos;
      EXPECT_EQ(refused_as_unknown, !kinds.count(kind))
          << "layout." << key << " on a " << kind << " layout: " << message;
    }
    for (const std::string& key : reading::layout_keys(layout_kind(kind)))
      EXPECT_TRUE(documented.count(key) && documented.at(key).count(kind))
          << "layout." << key << " is taken by a " << kind
          << " layout but patterns/README.md does not say so";
  }
}

}  // namespace curdle
