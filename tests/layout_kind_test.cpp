// Layout kinds are units: a kind defined here alone, registered with one line, gets every
// layout output from the same writers as the built-in kinds; the registry refuses what it must.
#include "layout/layout_kind.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

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
  EXPECT_NO_THROW(run_of(kStones, {"layout.kind=\"forgetful-stones\""}));
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

}  // namespace
}  // namespace curdle
