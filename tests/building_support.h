// Buildings the building tests share: the whole-buildings issue's L-shaped pavilion and curved
// garden wall, as recipe text, laid from a seed.
#pragma once

#include <string>

#include "curdle/curdling.h"
#include "kinds/registry.h"
#include "layout/builder.h"
#include "recipe/recipe.h"

namespace curdle::test {

// A façade spec of 215 x 65 mm bricks with 10 mm joints.
inline LayoutSpec bricks() {
  LayoutSpec spec;
  spec.set_kind(layout_kind("facade"));
  spec.module_w = 215, spec.module_h = 65, spec.joint = 10;
  return spec;
}

// The pavilion: 20 x 12 m with an 8 x 6 m bite, 7.05 m of 215 x 65 mm bricks, 10 mm joints;
// `building` is added to its [layout.building] table (openings, start, ...).
inline std::string pavilion_recipe(const std::string& building = "",
                                   const std::string& layout = "") {
  return R"(name = "pavilion"
seed = 7
[lattice]
base = 2
dimension = 2
[[curds]]
name = "dark"
probabilities = ["7/8", "4/5", "3/4", "2/3", "2/3"]
[layout]
kind = "facade"
panel = [215, 65]
joint = 10
)" + layout +
         R"([layout.building]
plan = [[0, 0], [20000, 0], [20000, 6000], [12000, 6000], [12000, 12000], [0, 12000]]
height = 7050
)" + building;
}

// A building of one two-stage curd: `layout` its [layout] keys (kind, unit, joint, bond),
// `building` its [layout.building] keys.
inline std::string building_recipe(const std::string& layout, const std::string& building) {
  return "name = \"building\"\nseed = 3\n[lattice]\nbase = 2\ndimension = 2\n[[curds]]\n"
         "probabilities = [\"7/8\", \"4/5\"]\n[layout]\nkind = \"facade\"\n" +
         layout + "[layout.building]\n" + building;
}

// A perforated screen of 3 mm sheet, 20 mm openings on a 50 mm grid, 1.6 m high along `path`
// (an arc of 8 m radius from (0, 0) sweeping 30°, unless given); `layout` adds [layout] keys.
inline std::string screen_recipe(
    const std::string& layout = "",
    const std::string& path = "[[0, 0], { centre = [0, 8000], sweep = 30 }]") {
  return "name = \"screen\"\nseed = 2\n[lattice]\nbase = 2\ndimension = 2\n[[curds]]\n"
         "probabilities = [\"0.9\", \"0.8\", \"0.8\"]\n[layout]\nkind = \"perforation\"\n"
         "cell = [50, 50]\nthickness = 3\nholes = [{ diameter = 20 }]\n" +
         layout + "[layout.building]\npath = " + path + "\nheight = 1600\n";
}

inline Layout lay_recipe(const std::string& text, uint64_t seed = 0) {
  const Recipe r = parse_recipe(text, "building.toml");
  const Design& d = r.design;
  return make_layout(d, curdle(d, seed ? seed : r.seed, d.field), d.field, *r.layout);
}

}  // namespace curdle::test
