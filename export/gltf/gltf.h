// layout.glb (or layout.gltf + layout.bin): the layout as a glTF 2.0 scene for Blender, Rhino,
// three.js and game engines. Metres, +Y up (glTF 2.0 specification, section 3.4). Floors lie on
// the XZ plane (layout y to -Z), walls and fins stand on the XY plane facing +Z.
//
// Every element is a node named by its element ID (as in layout.svg), its extras holding the
// value and the curd bits; the scene's extras hold the recipe, seed and lattice. One PBR
// material per value. Boxes share one mesh per material; park elements one mesh per type;
// a perforated sheet is one solid with its openings (CGAL constrained triangulation) and each
// opening an empty node; blocks are merged per value with the faces between neighbours left
// out, each block an empty node. The JSON is written by gltf_json.h, a node at a time.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "curdle/curd.h"
#include "layout/layout.h"

namespace curdle {

// Writes a binary glTF (.glb).
void write_glb(std::ostream& out, const Layout& layout);

// Writes a .gltf (JSON) whose buffer is the file `bin_name` beside it, written to `bin`.
void write_gltf(std::ostream& json, std::ostream& bin, const std::string& bin_name,
                const Layout& layout);

}  // namespace curdle
