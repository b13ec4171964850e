// Tests of park.h.
#include "kinds/park.h"

#include <gtest/gtest.h>

#include "layout/piece.h"
#include "layout_support.h"

namespace curdle {
using test::design;

TEST(Park, AnOutlineIsCoveredAndObjectsStandWholeInsideIt) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  LayoutSpec spec = test::trees_and_benches();
  // 48 x 48 m less a sloping cut across one corner and a step along x and y.
  const Polygon site = {{0, 0},         {30000, 0},     {48000, 20000}, {48000, 48000},
                        {20000, 48000}, {20000, 40000}, {0, 40000}};
  spec.outline = site;
  spec.size = std::array<double, 2>{48000, 48000};
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const Layout layout = lay_floor(d, spec, seed);
    double surfaces = 0;
    size_t shaped = 0;
    for (const Element& e : layout.elements) {
      if (e.type == "grey paving" || e.type == "white paving") {
        surfaces += e.area();
        shaped += e.outline.has_value();
        continue;
      }
      const Rect box = laid_bounds(e);
      for (const auto& corner : {std::array<double, 2>{box.x, box.y},
                                 {box.right(), box.y},
                                 {box.right(), box.top()},
                                 {box.x, box.top()}})
        EXPECT_TRUE(contains(site, corner[0], corner[1])) << e.id << " stands beyond the site";
    }
    EXPECT_NEAR(surfaces, polygon_area(site), 1e-2) << "seed " << seed;
    EXPECT_GT(shaped, 3u) << "surfaces along the sloping edge are cut to shape";
    std::ostringstream svg;
    write_layout_svg(svg, layout);
    EXPECT_NE(svg.str().find("id=\"outline\""), std::string::npos);
  }
}

TEST(Park, ElementsShareCellsWithoutOverlapAndSurfacesCoverTheArea) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  LayoutSpec spec = test::trees_and_benches();
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const CurdField f = curdle(d, seed, d.field);
    const Layout layout = make_layout(d, f, d.field, spec);
    std::map<std::pair<int64_t, int64_t>, std::vector<const Element*>> cells;
    std::map<std::string, uint64_t> per_type;
    double surfaces = 0;
    for (const Element& e : layout.elements) {
      cells[{e.row, e.column}].push_back(&e);
      ++per_type[e.type];
      if (e.type == "grey paving" || e.type == "white paving") surfaces += e.area();
    }
    EXPECT_NEAR(surfaces, layout.width * layout.height, 1e-3);  // surfaces tile the whole park
    const auto counts = value_counts(f);
    uint64_t trees = 0, benches = 0;
    for (uint32_t v = 0; v < 8; ++v)
      trees += (v & 1) ? counts[v] : 0, benches += (v & 2) ? counts[v] : 0;
    EXPECT_EQ(per_type["tree"], trees);
    EXPECT_EQ(per_type["bench"], benches);
    for (const auto& [cell, list] : cells) {
      std::vector<Rect> boxes;  // objects' footprints, to check clearances
      for (const Element* e : list) {
        if (e->type != "tree" && e->type != "bench") continue;
        const Rect box = e->circle
                             ? Rect{e->circle->cx - e->circle->d / 2,
                                    e->circle->cy - e->circle->d / 2, e->circle->d, e->circle->d}
                             : e->shape[0];
        const Rect& n = e->nominal;  // at least the clearance inside the cell
        EXPECT_GE(box.x - n.x, 300 - 1e-9);
        EXPECT_GE(n.right() - box.right(), 300 - 1e-9);
        EXPECT_GE(box.y - n.y, 300 - 1e-9);
        EXPECT_GE(n.top() - box.top(), 300 - 1e-9);
        for (const Rect& other : boxes) {  // and the clearance apart
          const double gap = std::max({other.x - box.right(), box.x - other.right(),
                                       other.y - box.top(), box.y - other.top()});
          EXPECT_GE(gap, 300 - 1e-9) << e->id;
        }
        boxes.push_back(box);
      }
    }
    SvgSummary svg = parse_svg(svg_of(layout));
    EXPECT_TRUE(svg.ids.count("type-tree") && svg.ids.count("type-bench") &&
                svg.ids.count("type-grey-paving"));
  }
}

}  // namespace curdle

namespace curdle {

// The clearance holds all round: an object stands at least `clearance` from its cell's edges
// and from the other objects in the cell, or is left out and the note says so. On 2 m cells
// with 300 mm clearance, two objects of 1000 mm once stood 75 mm from the cell's edge.
TEST(Park, ObjectsKeepTheirClearanceOrAreLeftOutWithANote) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  for (const double cell : {3000.0, 2000.0}) {
    LayoutSpec spec = test::trees_and_benches();
    spec.module_w = spec.module_h = cell;
    const double c = spec.own<ParkKeys>().clearance;
    const Layout layout = make_layout(d, curdle(d, 3, d.field), d.field, spec);
    std::map<std::pair<int64_t, int64_t>, std::vector<Rect>> objects;
    for (const Element& e : layout.elements) {
      if (!e.stands) continue;
      const Rect box = laid_bounds(e);
      const Rect cell_box{e.column * cell, e.row * cell, cell, cell};
      EXPECT_GE(box.x - cell_box.x, c - 1e-6) << e.id;
      EXPECT_GE(box.y - cell_box.y, c - 1e-6) << e.id;
      EXPECT_GE(cell_box.right() - box.right(), c - 1e-6) << e.id;
      EXPECT_GE(cell_box.top() - box.top(), c - 1e-6) << e.id;
      for (const Rect& other : objects[{e.row, e.column}]) {
        const double gap = std::max({other.x - box.right(), box.x - other.right(),
                                     other.y - box.top(), box.y - other.top()});
        EXPECT_GE(gap, c - 1e-6) << e.id;
      }
      objects[{e.row, e.column}].push_back(box);
    }
    bool noted = false;
    for (const std::string& note : layout.notes)
      noted |= note.find("with the clearance of 300 mm all round") != std::string::npos;
    EXPECT_EQ(noted, cell == 2000.0) << cell;  // 3 m cells hold both; 2 m cells cannot
  }
}

}  // namespace curdle

#include <sstream>

#include "export/schedules/park_schedules.h"
#include "recipe/recipe.h"

namespace curdle {

// A park's recipe takes [[layout.zones]] (it refused them as an unknown key, so the schedules'
// zone column was always empty): a play area kept free, a lawn of trees, named in planting.csv.
TEST(Park, ARecipesZonesAreLaidAndNamedInTheSchedules) {
  const std::string text = R"(name = "pz"
seed = 5
[lattice]
base = 4
dimension = 2
[[curds]]
name = "tree"
probabilities = ["3/4", "1/2"]
[[curds]]
name = "bench"
probabilities = ["1/2", "1/2"]
[layout]
kind = "park"
cell = [3000, 3000]
area = [48000, 48000]
clearance = 300
elements = [
  { type = "tree", form = "object", shape = "circle", size = [1000, 1000] },
  { type = "bench", form = "object", shape = "rectangle", size = [1000, 450] },
]
[[layout.zones]]
name = "play area"
rect = [3000, 3000, 9000, 9000]
rule = "exclude"
[[layout.zones]]
name = "west lawn"
rect = [24000, 0, 24000, 48000]
rule = "value"
value = 1
)";
  const Recipe r = parse_recipe(text, "pz.toml");
  ASSERT_EQ(r.layout->zones.size(), 2u);
  Design d = r.design;
  const Box view = r.window.value_or(d.field);
  const Layout layout = make_layout(d, curdle(d, r.seed, d.field), view, *r.layout);
  std::ostringstream planting;
  write_planting_csv(planting, layout);
  size_t in_lawn = 0;
  for (size_t at = planting.str().find(",west lawn"); at != std::string::npos;
       at = planting.str().find(",west lawn", at + 1))
    ++in_lawn;
  EXPECT_EQ(in_lawn, 128u);  // every cell of the lawn, 8 x 16, holds a tree and only a tree
  for (const Element& e : layout.elements) {
    const Rect b = laid_bounds(e);
    EXPECT_FALSE(b.x >= 3000 && b.right() <= 12000 && b.y >= 3000 && b.top() <= 12000)
        << e.id << " stands in the play area";
  }
}

}  // namespace curdle

#include "export/schedules/schedule.h"

namespace curdle {

// A park's surfaces are bought by area, one line per material, however the cells cut them; the
// lawn was split into six odd "stock sizes" sold in packs.
TEST(Park, SurfacesAreOrderedByAreaOneLineAMaterial) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  const LayoutSpec spec = test::trees_and_benches();
  const Layout layout = make_layout(d, curdle(d, 4, d.field), d.field, spec);
  std::ostringstream out;
  write_quantities_csv(out, layout);
  std::map<std::string, int> lines;
  double laid = 0;
  for (const Element& e : layout.elements)
    if (!e.stands) laid += std::round(e.area());
  double ordered = 0;
  std::istringstream rows(out.str());
  std::string row;
  std::getline(rows, row);
  while (std::getline(rows, row)) {
    if (row.find(",by area,") == std::string::npos) continue;
    ++lines[row.substr(0, row.find(','))];
    EXPECT_EQ(row.substr(row.size() - 3), ",,\r") << row;  // no pack size, no packs
    std::vector<std::string> f;
    std::istringstream cells(row);
    for (std::string cell; std::getline(cells, cell, ',');) f.push_back(cell);
    ordered += std::stod(f[8]) * 1e6;
  }
  EXPECT_EQ(lines["grey paving"], 1) << out.str();  // strips of cells shared with others too
  EXPECT_EQ(lines["white paving"], 1);
  EXPECT_NEAR(ordered, laid, 1.0);
}

}  // namespace curdle

namespace curdle {

// A tree's nursery sizes and pit are read from its element; a pit smaller than the root ball, a
// girth out of order or in NaN is refused by name; a tree whose pit would leave its cell (here
// the site's edge) is left out, with a note, where it stood before with its pit beyond the site.
TEST(Park, TreesCarrySpeciesGirthRootBallAndAPitWithinTheSite) {
  const std::string head = R"(name = "pits"
seed = 5
[lattice]
base = 2
dimension = 2
[[curds]]
name = "tree"
probabilities = ["1", "1"]
[layout]
kind = "park"
cell = [3000, 3000]
area = [11000, 12000]
elements = [
  { type = "tree", species = "Acer campestre", form = "object", shape = "circle", size = [1000, 1000], )";
  const Recipe r =
      parse_recipe(head + "girth = [16, 18], root_ball = 500, pit = [2000, 1200] },\n]\n", "p");
  const PlantingSpec& p = r.layout->own<ParkKeys>().elements[0].order;
  EXPECT_EQ(p.species, "Acer campestre");
  EXPECT_EQ(p.girth, (std::array<double, 2>{16, 18}));
  EXPECT_EQ(p.root_ball, 500);
  EXPECT_EQ(p.pit, (std::array<double, 2>{2000, 1200}));
  EXPECT_EQ(parse_recipe(head + "girth = 20 },\n]\n", "p")
                .layout->own<ParkKeys>()
                .elements[0]
                .order.girth,
            (std::array<double, 2>{20, 20}));
  for (const auto& [keys, says] : std::vector<std::pair<std::string, std::string>>{
           {"root_ball = 800, pit = [2000, 700]", "each side at least its 800 mm"},
           {"girth = [18, 16]", "from <= to"},
           {"girth = nan", "girth"},
           {"girth = [18, 16, 14]", "girth"},
           {"pit = [0, 1000]", "pit"}}) {
    try {
      parse_recipe(head + keys + " },\n]\n", "p");
      ADD_FAILURE() << keys << " was taken";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
  // Cells 3 m, the site 11 m wide: the fourth column's cell is 2 m wide. A 2 m pit may reach
  // past its cell into the neighbour's ground, never past the site's edge or into another pit:
  // the pits had to lie within their cells, and that column's trees were all left out.
  Design d = r.design;
  const Layout layout = make_layout(d, curdle(d, r.seed, d.field), d.field, *r.layout);
  std::vector<Rect> pits;
  size_t past_the_cell = 0;
  for (const Element& e : layout.elements) {
    if (!e.stands) continue;
    const std::optional<Rect> pit = tree_pit(layout, e);
    ASSERT_TRUE(pit) << e.id;
    EXPECT_GE(pit->x, -1e-9) << e.id;
    EXPECT_GE(pit->y, -1e-9) << e.id;
    EXPECT_LE(pit->right(), layout.width + 1e-9) << e.id;
    EXPECT_LE(pit->top(), layout.height + 1e-9) << e.id;
    for (const Rect& other : pits) EXPECT_FALSE(overlaps(other, *pit)) << e.id;
    past_the_cell += pit->x < e.nominal.x - 1e-9 || pit->right() > e.nominal.right() + 1e-9;
    pits.push_back(*pit);
  }
  EXPECT_GE(pits.size(), 14u);  // of 16 cells; 12 when pits kept to their cells
  EXPECT_GT(past_the_cell, 0u);
}

// Trees stand where their cell's own stream puts them in their slot, not on a grid at the
// cells' centres; a cell places its tree alike in any window of the field (the stream is keyed
// by the field cell), and a zone asks for trees by the curd's name.
TEST(Park, TreesStandOffTheGridAsTheirCellsDrawThem) {
  const Design d = test::design(4, 2, {{"1", "1"}, {"1/2", "1/2"}, {"1/2", "1/2"}});
  LayoutSpec spec = test::trees_and_benches();
  spec.size = std::array<double, 2>{24000, 24000};
  const Layout layout = lay_floor(d, spec, 7);
  std::set<long> offsets_x, offsets_y;
  size_t trees = 0;
  for (const Element& e : layout.elements) {
    if (!e.stands || !e.circle) continue;
    ++trees;
    offsets_x.insert(std::lround(e.circle->cx - (e.nominal.x + e.nominal.w / 2)));
    offsets_y.insert(std::lround(e.circle->cy - (e.nominal.y + e.nominal.h / 2)));
    // Whole in the cell, clear of its edges by the clearance.
    EXPECT_GE(e.circle->cx - 500, e.nominal.x + 300 - 1e-9) << e.id;
    EXPECT_LE(e.circle->cy + 500, e.nominal.top() - 300 + 1e-9) << e.id;
  }
  ASSERT_GE(trees, 30u);
  EXPECT_GT(offsets_x.size(), trees / 2);  // one offset for every tree on a grid
  EXPECT_GT(offsets_y.size(), trees / 2);
  // The same seed places every tree of a cell alike in a window of a larger field.
  Design larger = d;
  larger.field.size = {16, 16, 1};
  const CurdField big = curdle(larger, 7, larger.field);
  const Box window{{0, 0, 0}, {8, 8, 1}};
  const Layout again = make_layout(larger, big, window, spec);
  std::map<std::string, std::array<double, 2>> at;
  for (const Element& e : layout.elements)
    if (e.circle) at[e.id] = {e.circle->cx, e.circle->cy};
  size_t same = 0;
  for (const Element& e : again.elements)
    if (e.circle && at.count(e.id) && at[e.id] == std::array<double, 2>{e.circle->cx, e.circle->cy})
      ++same;
  EXPECT_GT(same, 0u);
}

// A bench turns to face the nearest piece of the path it is to face (the ground by default,
// or a surface or zone the recipe names), its long side square to that way; an unknown name
// is refused with those that exist.
TEST(Park, BenchesFaceThePathOrTheZoneNamed) {
  const Design d = test::design(4, 2, {{"1/2", "1/2"}, {"3/4", "3/4"}, {"1/2", "1/2"}});
  LayoutSpec spec = test::trees_and_benches();
  spec.size = std::array<double, 2>{24000, 24000};
  const Layout layout = lay_floor(d, spec, 3);
  std::vector<Rect> ground;
  for (const Element& e : layout.elements)
    if (e.type == "white paving") ground.push_back(laid_bounds(e));
  size_t benches = 0;
  for (const Element& e : layout.elements) {
    if (e.type != "bench") continue;
    ++benches;
    const Rect b = laid_bounds(e);
    const int facing = static_cast<int>(e.turn);
    EXPECT_EQ(b.w > b.h, facing % 180 == 0) << e.id;  // 1000 x 450: its front is the long side
    // Its backrest, drawn thick, on the side away from the way it faces.
    const auto back = back_edge(e);
    ASSERT_TRUE(back) << e.id;
    const double bx = ((*back)[0][0] + (*back)[1][0]) / 2, by = ((*back)[0][1] + (*back)[1][1]) / 2;
    EXPECT_TRUE((facing == 0 && by == b.y) || (facing == 180 && by == b.top()) ||
                (facing == 90 && bx == b.x) || (facing == 270 && bx == b.right()))
        << e.id;
    // Some ground lies that way from its front, outside its own cell.
    const double cx = b.x + b.w / 2, cy = b.y + b.h / 2;
    bool ahead = false;
    for (const Rect& g : ground) {
      if (overlaps(g, e.nominal)) continue;
      ahead |= (facing == 0 && g.y >= cy) || (facing == 180 && g.top() <= cy) ||
               (facing == 90 && g.x >= cx) || (facing == 270 && g.right() <= cx);
    }
    EXPECT_TRUE(ahead) << e.id << " faces " << facing;
  }
  ASSERT_GT(benches, 3u);
  // Facing a zone: a bench west of it faces east.
  LayoutSpec zoned = spec;
  Zone lawn;
  lawn.name = "lawn";
  lawn.rule = ZoneRule::value;
  lawn.value = 0;
  lawn.polygon = {{20000, 0}, {24000, 0}, {24000, 24000}, {20000, 24000}};
  zoned.zones = {lawn};
  zoned.own<ParkKeys>().elements[1].faces = "lawn";
  const Layout facing_lawn = lay_floor(d, zoned, 3);
  size_t east = 0, all = 0;
  for (const Element& e : facing_lawn.elements)
    if (e.type == "bench" && e.nominal.right() <= 20000) ++all, east += e.turn == 90;
  ASSERT_GT(all, 0u);
  EXPECT_EQ(east, all);
}

// A zone asks for trees by the curd's name, and a bench's `faces` must name a surface or a
// zone: anything else is refused with the names there are.
TEST(Park, ZonesAskForTreesByNameAndFacesNamesWhatExists) {
  const std::string head = R"(name = "grove"
[lattice]
base = 2
dimension = 2
[[curds]]
name = "tree"
probabilities = ["1/2", "1/2"]
[[curds]]
name = "bench"
probabilities = ["1/2", "1/2"]
[layout]
kind = "park"
cell = [3000, 3000]
area = [12000, 12000]
zones = [{ name = "grove", rect = [0, 0, 6000, 6000], rule = "value", value = "tree" }]
)";
  const std::string elements =
      "elements = [{ type = \"tree\", shape = \"circle\", size = [1000, 1000] },\n"
      "  { type = \"bench\", shape = \"rectangle\", size = [1500, 500], faces = ";
  const Recipe r = parse_recipe(head + elements + "\"grove\" }]\n", "p");
  EXPECT_EQ(r.layout->zones.at(0).value, 1u);
  Design d = r.design;
  const Layout layout = make_layout(d, curdle(d, 2, d.field), d.field, *r.layout);
  size_t in_grove = 0;
  for (const Element& e : layout.elements)
    if (e.stands && e.circle && e.circle->cx < 6000 && e.circle->cy < 6000) ++in_grove;
  EXPECT_EQ(in_grove, 4u);  // every cell of the zone holds a tree
  for (const auto& [value, says] : std::vector<std::pair<std::string, std::string>>{
           {"\"oak\" }]",
            "joined with \"+\" as the legend names them (tree+bench): \"tree\", \"bench\""},
           {"\"pond\" }]", "no surface's type or zone's name here: \"white paving\", \"grove\""}}) {
    const bool zone = value.find("oak") != std::string::npos;
    std::string text = head + elements + (zone ? "\"grove\" }]" : value) + "\n";
    if (zone) text.replace(text.find("value = \"tree\""), 14, "value = \"oak\"");
    try {
      parse_recipe(text, "p");
      ADD_FAILURE() << value << " was taken";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

}  // namespace curdle
