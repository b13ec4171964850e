// The colour under a layout's pieces on every drawing (layout.png, layout.svg, layout.pdf): a
// perforated sheet's metal, the joints' colour, or, where the pieces meet with no joints, the
// most common value's colour, which hides the seams a renderer's smoothing lets through; lines,
// blocks, parks and kept curds stand on white.
#pragma once

#include "curdle/curd.h"
#include "layout/layout.h"

namespace curdle {

inline constexpr Rgb kSheetMetal{201, 205, 210};

Rgb ground_colour(const Layout& layout);

}  // namespace curdle
