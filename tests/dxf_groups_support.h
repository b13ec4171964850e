// The groups of one entity written as DXF text ("5\n60\n8\nL\n..."), for the tests of the
// readers that take an entity's groups (dxf_hatch.h, dxf_spline.h).
#pragma once

#include <string>
#include <vector>

#include "site/dxf_groups.h"

namespace curdle::testing {

// Holds the text the groups' values view.
struct EntityGroups {
  explicit EntityGroups(std::string dxf) : text(std::move(dxf)), numbers(text, "site.dxf") {
    site::DxfGroup g;
    while (numbers.next(g)) groups.push_back(g);
  }
  std::string text;
  site::DxfGroups numbers;
  std::vector<site::DxfGroup> groups;
};

}  // namespace curdle::testing
