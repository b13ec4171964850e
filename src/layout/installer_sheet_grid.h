// The grid of installer's sheets over a layout: where the sheets meet (at joints where the
// slack allows), the match-line captions on both sides of every shared edge, the start corner's
// area, and the bound on a named scale's set. The labels on the sheets are installer_sheets.cpp's.
#pragma once

#include <vector>

#include "layout/installer_sheets.h"

namespace curdle {

// Lays the grid of sheets at 1 : scale over `pieces` into `plan`: its scale, sheets, edges,
// captions and start corner (its paper and viewport already set).
void lay_sheets(const std::vector<InstallerPiece>& pieces, double scale, const Layout& layout,
                InstallerPlan& plan);

// A named scale is taken as asked unless its set would be more than kMostInstallerSheets:
// InputError naming the scale that fits.
void check_named_scale(const Layout& layout, const InstallerPlan& plan, double scale);

}  // namespace curdle
