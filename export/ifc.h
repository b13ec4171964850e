// layout.ifc: the layout as a BIM model, IFC4 (ADD2 TC1) in STEP form, lengths in millimetres,
// so that Revit, ArchiCAD, BricsCAD BIM, Vectorworks or Solibri load every element with its
// data. A project with a site (ground works: paving, tiles, parks) or a site, a building and a
// storey (façades, screens, blocks), and one element per row of schedule.csv, named and tagged
// by its ID:
//   tiles, paving and façade pieces  IfcCovering FLOORING, or CLADDING on an upright surface,
//                                    typed by an IfcCoveringType per material and stock size
//                                    (with Pset_Tiling's TileLength and TileWidth);
//   perforations                     an IfcPlate per fabrication sheet, each opening an
//                                    IfcOpeningElement voiding it (IfcRelVoidsElement);
//   parks                            surfaces as IfcCovering FLOORING, trees as
//                                    IfcGeographicElement, other objects as IfcFurniture;
//   blocks                           IfcBuildingElementProxy.
// Each element is an extruded solid as laid (cut pieces by their own outline) in its value's
// colour, with its material (IfcMaterial, the schedule's), a property set Curdle_Element
// (value, curd bits, row, column, lot, cut, stock size) and base quantities. The project
// carries Curdle_Recipe (recipe, seed, lattice, window) to reproduce it. GlobalIds are derived
// from the recipe, seed, window and element ID, and the time stamp is fixed: the same run gives
// the same bytes.
#pragma once

#include <ostream>

#include "layout/layout.h"

namespace curdle {

void write_layout_ifc(std::ostream& out, const Layout& layout);

}  // namespace curdle
