// install.svg: the installer's map. Every element drawn at its place, in true millimetres,
// labelled with its ID; rows numbered from the origin corner and an arrow showing where laying
// starts and which way it runs. Perforated sheets show their openings' IDs and each sheet.
#pragma once

#include <ostream>

#include "layout/layout.h"

namespace curdle {

void write_install_svg(std::ostream& out, const Layout& layout);

}  // namespace curdle
