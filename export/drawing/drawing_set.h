// layout.pdf, the drawing set, and layout.png, its first sheet as a picture; drawn with cairo
// on ISO sheets in millimetres.
//
// Sheet 1 is the whole layout at a standard scale (drawing_sheet.h) with a legend of counts, a
// quantities table, a scale bar, the origin and start corner, and the title block. The
// installer's sheets follow (installer_sheets.h): the layout cut into a grid of sheets at a
// scale where every ID reads, each with row and column numbers, match lines naming the sheet
// beyond, a key plan showing where it lies, the start corner, and "sheet k of n".
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "io/image.h"
#include "layout/drawing_sheet.h"
#include "layout/installer_sheets.h"
#include "layout/layout.h"

namespace curdle {

// The sheet the whole layout is drawn on: its paper, orientation and scale. With layout.scale
// given, the smallest ISO sheet from layout.paper up that holds the drawing; InputError when
// not even A0 does.
struct OverviewSheet {
  PaperSheet paper;
  bool landscape = true;
  double scale = 1;
};
OverviewSheet overview_sheet(const Layout& layout);

// Sheet 1's legend, a swatch (none, one, or a kept element's stripes) and a line each: a park's
// materials as planted and built, else one line a product with its values, count, cut pieces
// and area; a building's units then by part (stretchers, headers, closers, each special), as
// quantities.csv has them, and a one-brick wall's backing (drawing_set_legend.cpp).
std::vector<std::pair<std::vector<Rgb>, std::string>> sheet_legend(const Layout& layout);

// The drawing set as PDF 1.5: sheet 1 and the installer's sheets of `plan`.
void write_layout_pdf(std::ostream& out, const Layout& layout, const InstallerPlan& plan);

// Sheet 1 at layout.dpi, the layout itself as render_layout draws it (so that its pixels are
// the same), everything else as in layout.pdf (whose sheets `plan` gives).
PreviewImage render_layout_sheet(const Layout& layout, const InstallerPlan& plan);

// layout.png's bytes: render_layout_sheet's pixels at layout.dpi, encoded as they are read off
// the sheet rather than copied into a picture first.
std::string layout_sheet_png(const Layout& layout, const InstallerPlan& plan);

// Pixels of the sheet layout.png is for a layout of `spec`, known before it is built (the
// layout's own picture on it is render_layout's: layout_png_pixels).
uint64_t layout_sheet_pixels(const LayoutSpec& spec);

}  // namespace curdle
