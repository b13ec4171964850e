#include "export/ifc/ifc_standard_sets.h"

#include "export/ifc/step_file.h"

namespace curdle {
namespace {

IfcSetEntry identifier(const std::string& name, const std::string& value) {
  return {IfcSetEntry::Kind::property, name, "IFCIDENTIFIER(" + step_string(value) + ")", 0};
}
IfcSetEntry boolean(const std::string& name, bool value) {
  return {IfcSetEntry::Kind::property, name, value ? "IFCBOOLEAN(.T.)" : "IFCBOOLEAN(.F.)", 0};
}
IfcSetEntry quantity(IfcSetEntry::Kind kind, const std::string& name, double amount) {
  return {kind, name, {}, amount};
}

// Reference, and IsExternal where it is known.
IfcSet common(const std::string& name, const IfcMeasures& m) {
  IfcSet set{name, {identifier("Reference", m.reference)}};
  if (m.known_exposure) set.entries.push_back(boolean("IsExternal", m.external));
  return set;
}

}  // namespace

std::vector<IfcSet> standard_sets(std::string_view entity, const IfcMeasures& m) {
  using K = IfcSetEntry::Kind;
  const double volume = m.volume >= 0 ? m.volume : m.net_area * m.thickness / 1000,
               gross_volume = m.volume >= 0 ? m.volume : m.gross_area * m.thickness / 1000;
  if (entity == "IFCCOVERING")
    return {
        common("Pset_CoveringCommon", m),
        {"Qto_CoveringBaseQuantities",
         {quantity(K::length, "Width", m.thickness), quantity(K::area, "GrossArea", m.gross_area),
          quantity(K::area, "NetArea", m.net_area)}}};
  if (entity == "IFCPLATE") {
    IfcSet pset = common("Pset_PlateCommon", m);
    pset.entries.push_back(boolean("LoadBearing", false));
    return {
        pset,
        {"Qto_PlateBaseQuantities",
         {quantity(K::length, "Width", m.thickness), quantity(K::area, "GrossArea", m.gross_area),
          quantity(K::area, "NetArea", m.net_area),
          quantity(K::volume, "GrossVolume", gross_volume),
          quantity(K::volume, "NetVolume", volume)}}};
  }
  if (entity == "IFCOPENINGELEMENT")
    return {{"Pset_OpeningElementCommon", {identifier("Reference", m.reference)}},
            {"Qto_OpeningElementBaseQuantities",
             {quantity(K::length, "Width", m.width), quantity(K::length, "Height", m.height),
              quantity(K::length, "Depth", m.thickness), quantity(K::area, "Area", m.net_area),
              quantity(K::volume, "Volume", volume)}}};
  if (entity == "IFCBUILDINGELEMENTPROXY")
    return {common("Pset_BuildingElementProxyCommon", m),
            {"Qto_BuildingElementProxyQuantities",
             {quantity(K::area, "NetSurfaceArea", m.net_area),
              quantity(K::volume, "NetVolume", volume)}}};
  return {};
}

IfcClass class_of(const Layout& layout, const Element& e) {
  switch (e.form) {
    case ElementForm::opening:  // a sheet's hole, in its body: no opening to subtract
      return {"IFCANNOTATION", ""};
    case ElementForm::block:
      return {"IFCBUILDINGELEMENTPROXY", ".ELEMENT."};
    case ElementForm::object:
      if (e.circle) return {"IFCGEOGRAPHICELEMENT", ".USERDEFINED."};
      if (e.stands) return {"IFCFURNITURE", ".USERDEFINED."};
      return {"IFCCOVERING", ".FLOORING."};
    case ElementForm::piece:
    case ElementForm::cut_piece:
      break;
  }
  // A building's units are the parts its walls are made of.
  if (layout.envelope) return {"IFCBUILDINGELEMENTPART", ".USERDEFINED."};
  return {"IFCCOVERING", layout.kind->upright() ? ".CLADDING." : ".FLOORING.", true};
}

}  // namespace curdle
