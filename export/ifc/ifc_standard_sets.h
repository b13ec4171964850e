// The property and quantity sets of IFC4's standard (Pset_*Common, Qto_*BaseQuantities) an
// element carries beside curdle's own, so that Revit, ArchiCAD, Solibri or a quantity take-off
// find its reference, whether it is external, its thickness and its areas where they look for
// them. Lengths in the project's millimetres, areas in m², volumes in m³.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "layout/layout.h"

namespace curdle {

// What an element measures, as the standard sets ask for it.
struct IfcMeasures {
  std::string reference;         // the element's ID
  bool external = false;         // on a façade or out of doors
  bool known_exposure = false;   // whether `external` is known (floor tiles may be indoors)
  double thickness = 0;          // mm, through the element
  double width = 0, height = 0;  // mm, its extent in the surface's plane
  double gross_area = 0;         // m², not taking out what is cut away inside it
  double net_area = 0;           // m², as laid
  double volume = -1;            // m³ of a body that is no prism of net_area x thickness (a
                                 // tree's trunk and canopy); < 0: that prism's
};

// One property of a set: its name and its value as a typed STEP literal ("IFCBOOLEAN(.T.)").
struct IfcSetEntry {
  enum class Kind { property, length, area, volume };
  Kind kind = Kind::property;
  std::string name;
  std::string value;  // a property's typed literal
  double amount = 0;  // a quantity's
};

struct IfcSet {
  std::string name;  // "Pset_CoveringCommon", "Qto_CoveringBaseQuantities"
  std::vector<IfcSetEntry> entries;
};

// The standard sets of an element of IFC class `entity` ("IFCCOVERING", "IFCPLATE", ...), both
// the common property set and the base quantities; none for classes IFC4 gives none.
std::vector<IfcSet> standard_sets(std::string_view entity, const IfcMeasures& m);

// What an element becomes in the model: its IFC4 class, whose standard sets it carries.
struct IfcClass {
  const char* entity;      // IFCCOVERING, ...
  const char* predefined;  // its PredefinedType (an IfcAnnotation has none)
  bool typed = false;      // grouped by an IfcCoveringType
};

IfcClass class_of(const Layout& layout, const Element& e);

}  // namespace curdle
