// Well-known text (OGC Simple Features) of piece outlines, in millimetres: what GIS, CAD and
// spreadsheet users read as a polygon.
#pragma once

#include <string>
#include <vector>

#include "layout/layout.h"

namespace curdle {

// A length in millimetres as the files write it: to the micrometre, without trailing zeros.
std::string mm_text(double v);
void append_mm_text(std::string& out, double v);  // the same, written at the end of `out`

// POLYGON for one part, MULTIPOLYGON for several; rings closed; "" for none.
std::string outlines_wkt(const std::vector<Outline>& outlines);
void append_outlines_wkt(std::string& out, const std::vector<Outline>& outlines);

}  // namespace curdle
