// Layout kinds are units: a kind defined here alone, registered with one line, gets every
// layout output from the same writers as the built-in kinds; the registry refuses what it must.
#include "layout/layout_kind.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "app/outputs.h"
#include "app/run.h"
#include "curdle/error.h"
#include "kinds/registry.h"
#include "layout/builder.h"
#include "recipe/layout_reader.h"

namespace curdle {
namespace {

// Stepping stones across a lawn: one stone per cell where a curd survived, inset in its cell.
// The kind's own key: `inset`, the lawn left around each stone.
struct StoneKeys : KindKeysOf<StoneKeys> {
  double inset = 0;
};

class SteppingStones : public LayoutKind {
 public:
  std::string_view name() const override { return "stepping-stones"; }
  std::string_view element_noun() const override { return "stone"; }
  char id_letter() const override { return 'S'; }
  double thickness(const LayoutSpec&) const override { return 40; }
  Ground ground() const override { return Ground::paper; }
  Depiction depiction() const override { return Depiction::shapes; }
  std::vector<std::string> keys() const override { return {"cell", "inset"}; }
  std::unique_ptr<KindKeys> default_keys() const override { return std::make_unique<StoneKeys>(); }
  void read(reading::TableReader& r, Design& design, LayoutSpec& spec, bool) const override {
    const auto cell = reading::read_mm_pair(r, "cell", true);
    spec.module_w = (*cell)[0], spec.module_h = (*cell)[1];
    spec.own<StoneKeys>().inset = reading::read_mm(r, "inset", 50, 0);
    reading::read_value_colours(r, design, spec);
    reading::read_drawing_scale(r, spec);
  }
  Layout build(const Design& design, const CurdField& field, const Box& view,
               const LayoutSpec& spec) const override {
    Layout layout = lay_grid(design, field, view, spec, {});
    count_values(layout, design, spec);
    const double inset = spec.own<StoneKeys>().inset;
    std::erase_if(layout.elements, [](const Element& e) { return e.value == 0; });
    for (Element& e : layout.elements) {
      const Rect& n = e.nominal;
      e.shape = {Rect{n.x + inset, n.y + inset, n.w - 2 * inset, n.h - 2 * inset}};
      e.stock_w = e.shape[0].w, e.stock_h = e.shape[0].h;
    }
    return layout;
  }
};

const char* kStones = R"(name = "stones"
[lattice]
base = 2
dimension = 2
[[curds]]
name = "stone"
probabilities = ["3/4", "2/3", "2/3"]
[field]
cells = [8, 8]
[layout]
kind = "stepping-stones"
cell = [600, 600]
inset = 75
materials = ["lawn", "Granite"]
)";

app::Run run_of(const std::string& text, std::vector<std::string> overrides = {}) {
  app::RunRequest request;
  request.recipe_text = text;
  request.recipe_path = "stones.toml";
  request.overrides = std::move(overrides);
  return app::resolve_run(request);
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

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
  EXPECT_THROW(register_layout_kind(std::make_unique<Another>()), std::logic_error);
  // An unknown kind's message lists the registered ones.
  try {
    run_of(kStones, {"layout.kind=\"lawn\""});
    FAIL() << "an unknown kind was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"tile\", \"paving\", \"facade\""), std::string::npos)
        << e.what();
  }
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
  EXPECT_THROW(run_of(kStones, {"layout.kind=\"forgetful-stones\""}), std::logic_error);
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

// Each key of patterns/README.md's tables is taken by the kinds it names and refused by the
// others; every key a kind takes is documented for it.
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

}  // namespace
}  // namespace curdle
