// install.svg: the installer's map. The whole layout at the installer's sheets' scale, every
// piece labelled as on those sheets (installer_sheets.h: IDs at least 2 mm on paper, in their
// piece or beside it with a leader, never two on one another), the sheets' grid numbered as in
// layout.pdf, rows and columns numbered, and where laying starts. A perforated surface is
// installed as its fabrication sheets: they carry the IDs, its openings are drawn.
#pragma once

#include <ostream>

#include "layout/installer_sheets.h"
#include "layout/layout.h"

namespace curdle {

void write_install_svg(std::ostream& out, const Layout& layout, const InstallerPlan& plan);

}  // namespace curdle
