// Reads an architect's massing model, glTF 2.0 (.glb, or .gltf with its buffers embedded), into
// a Drawing: each named node that holds a mesh becomes a layer holding the outline of its
// footprint, the boundary of its lowest horizontal faces in plan (x east, y north from glTF's
// x and -z), so that a building's plan is read from the model as from a plan layer of a DXF.
// A mesh's arcs are its facets: the outline is a polygon. Nothing outside the file is read.
#pragma once

#include <string>
#include <string_view>

#include "site/drawing.h"

namespace curdle::site {

// Throws InputError naming the file for one that is not glTF 2.0, refers to files outside it,
// is larger than kMostDrawingBytes, or holds more than kMostVertices vertices; a node whose
// footprint is not one closed outline (a courtyard, a pile of loose faces) is named as such.
Drawing read_gltf(std::string_view bytes, const std::string& file_name);

}  // namespace curdle::site
