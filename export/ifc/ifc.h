// layout.ifc: the layout as a BIM model, IFC4 (ADD2 TC1) in STEP form, lengths in millimetres,
// so that Revit, ArchiCAD, BricsCAD BIM, Vectorworks or Solibri load every element with its
// data. A project with a site, and façades, screens and blocks in a building's storey or ground
// works (paving, tiles, parks) in an external space on the site; one element per row of
// schedule.csv, named and tagged by its ID (an annotation has no tag):
//   tiles, paving and façade pieces  IfcCovering FLOORING, or CLADDING on an upright surface,
//                                    typed by an IfcCoveringType per material and stock size
//                                    (with Curdle_Tiling's TileLength and TileWidth: IFC4 has no
//                                    set for a tile's size);
//   perforations                     an IfcPlate per fabrication sheet, its openings holes in
//                                    its profile, each an IfcAnnotation drawn by its outline
//                                    and assigned to it (IfcRelAssignsToProduct): nothing for
//                                    a reader to subtract;
//   parks                            surfaces as IfcCovering FLOORING, trees as
//                                    IfcGeographicElement, other objects as IfcFurniture;
//   blocks                           IfcBuildingElementProxy.
// Each element is placed at its own corner relative to its container (ifc_geometry.h draws it
// from there) and is one extruded solid as laid, whatever its shape (a tree: trunk and canopy),
// in its value's colour, with its material (IfcMaterial, the schedule's), IFC4's standard sets
// (ifc_standard_sets.h), a property set Curdle_Element (value, curd bits, row, column, lot,
// cut, stock size) and Curdle_Quantities. One IfcOwnerHistory names curdle. The project carries
// Curdle_Recipe (recipe, seed, lattice, window) to reproduce it. GlobalIds are derived from the
// recipe, seed, window and element ID, and the time stamps are fixed: the same run gives the
// same bytes.
#pragma once

#include <ostream>

#include "layout/layout.h"

namespace curdle {

void write_layout_ifc(std::ostream& out, const Layout& layout);

}  // namespace curdle
