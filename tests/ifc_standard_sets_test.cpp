// IFC4's standard sets per class: the names BIM tools look for, the reference, whether the
// element is external only where that is known, and quantities in the model's units.
#include "export/ifc/ifc_standard_sets.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {

const IfcSetEntry* entry(const IfcSet& set, const std::string& name) {
  for (const IfcSetEntry& e : set.entries)
    if (e.name == name) return &e;
  return nullptr;
}

TEST(IfcStandardSets, ACoveringHasItsCommonSetAndBaseQuantities) {
  const IfcMeasures m{"P-R01-C02", true, true, 30, 600, 300, 0.18, 0.15};
  const std::vector<IfcSet> sets = standard_sets("IFCCOVERING", m);
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_EQ(sets[0].name, "Pset_CoveringCommon");
  EXPECT_EQ(entry(sets[0], "Reference")->value, "IFCIDENTIFIER('P-R01-C02')");
  EXPECT_EQ(entry(sets[0], "IsExternal")->value, "IFCBOOLEAN(.T.)");
  EXPECT_EQ(sets[1].name, "Qto_CoveringBaseQuantities");
  EXPECT_EQ(entry(sets[1], "Width")->amount, 30);  // the covering's thickness
  EXPECT_EQ(entry(sets[1], "GrossArea")->amount, 0.18);
  EXPECT_EQ(entry(sets[1], "NetArea")->amount, 0.15);
}

TEST(IfcStandardSets, WhetherAnElementIsExternalIsSaidOnlyWhereItIsKnown) {
  const IfcMeasures indoors_or_not{"T-R00-C00", false, false, 10, 300, 300, 0.09, 0.09};
  EXPECT_EQ(entry(standard_sets("IFCCOVERING", indoors_or_not)[0], "IsExternal"), nullptr);
}

TEST(IfcStandardSets, PlatesOpeningsAndProxiesHaveTheirsAndOtherClassesNone) {
  const IfcMeasures m{"X", true, true, 3, 12, 12, 3.0, 2.5};
  const auto plate = standard_sets("IFCPLATE", m);
  ASSERT_EQ(plate.size(), 2u);
  EXPECT_EQ(plate[1].name, "Qto_PlateBaseQuantities");
  EXPECT_EQ(entry(plate[0], "LoadBearing")->value, "IFCBOOLEAN(.F.)");
  EXPECT_NEAR(entry(plate[1], "NetVolume")->amount, 2.5 * 3 / 1000, 1e-12);  // m³
  const auto opening = standard_sets("IFCOPENINGELEMENT", m);
  ASSERT_EQ(opening.size(), 2u);
  EXPECT_EQ(opening[1].name, "Qto_OpeningElementBaseQuantities");
  EXPECT_EQ(entry(opening[1], "Depth")->amount, 3);
  EXPECT_EQ(standard_sets("IFCBUILDINGELEMENTPROXY", m)[1].name,
            "Qto_BuildingElementProxyQuantities");
  EXPECT_TRUE(standard_sets("IFCFURNITURE", m).empty());
  EXPECT_TRUE(standard_sets("IFCGEOGRAPHICELEMENT", m).empty());
  EXPECT_TRUE(standard_sets("IFCANNOTATION", m).empty());  // a sheet's hole
}

}  // namespace
}  // namespace curdle
