// The installer's sheets: the layout cut into a grid of ISO sheets at a standard scale where
// every piece's ID can be read on paper (text at least 2 mm high) and no two labels overlap.
//
// A label sits inside its piece when it fits there, across or along it; otherwise (a sliver at
// an edge or an opening) beside it with a leader, at the nearest free place on the same sheet.
// The scale is the largest standard one at which a typical piece holds its label and every
// label finds a place; each sheet keeps the labels of the pieces whose centre it holds. Sheets
// meet where the fewest pieces cross (at joints), so that match lines do not split pieces; no
// label lies on a match line's caption or on the start corner.
// Small units (bricks, setts, mosaic: layout.installer_set) are drawn as a coursed set instead:
// each piece in its value's colour and hatch, courses and columns numbered, no IDs.
// Perforated surfaces are installed as panels: their pieces are the fabrication sheets (the
// openings are cut from the sheets' DXFs by their own IDs).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "layout/drawing_sheet.h"
#include "layout/layout.h"

namespace curdle {

// Text of IDs on the installer's sheets, mm of capital height on paper (ISO 3098's h): 2.5
// where the pieces have room, never below 2 (row and column numbers are 2.5).
inline constexpr double kInstallerTextMm = 2.5;
inline constexpr double kInstallerMinTextMm = 2.0;
// DejaVu Sans: capitals are 0.729 em high, so the font size is text / 0.729.
inline constexpr double kCapHeightEm = 0.729;
// The width of a label of `characters` on paper, mm: 0.7 em a character (the widest letters
// in IDs, R and C, are 0.70 em; digits 0.64), 0.96 capital heights, and room either side; its
// height a line, 1.7 capital heights.
double label_width_mm(size_t characters, double text_mm);
double label_height_mm(double text_mm);

// The pieces an installer lays (their IDs and the rectangles they cover, layout mm).
struct InstallerPiece {
  std::string id;
  std::vector<Rect> parts;
  Rect bounds;
  const Outline* outline = nullptr;  // a piece cut along a sloping or curved edge: drawn by it
};

struct InstallerLabel {
  std::string text;                    // the piece's ID
  Rect box;                            // layout mm
  bool rotated = false;                // reads bottom to top
  bool inside = true;                  // in its piece; else beside it, with a leader from `anchor`
  std::array<double, 2> anchor{0, 0};  // the piece's centre, layout mm
  size_t sheet = 0;                    // index into InstallerPlan::sheets
  bool crowded = false;  // walled in: its leader may run over other labels (InstallerPlan)
  size_t split = 0;      // set in two lines, broken at this '-' of the ID; 0: one line
};
// The label's lines as set: the ID, or its two halves (P-R05 over C14) where the piece holds
// it only so.
std::vector<std::string> label_lines(const InstallerLabel& label);
// A label beside its piece is joined to it by a leader: a dot at the piece's centre (radius in
// paper mm) and a line to the label box's nearest point, which crosses no other label or leader.
inline constexpr double kLeaderDotMm = 0.4;
std::array<double, 2> leader_end(const InstallerLabel& label);

struct InstallerSheet {
  size_t row = 0, column = 0;  // in the grid, from the bottom-left
  Rect window;                 // the part of the layout it shows, layout mm
};

// A match line's caption ("match line: sheet 7"), inside its sheet along the shared edge; no
// label is placed on it.
struct MatchCaption {
  size_t sheet = 0, other = 0;  // indices into InstallerPlan::sheets
  Rect box;                     // layout mm
  bool vertical = false;        // on a left or right edge, reading bottom to top
};
inline constexpr double kMatchCaptionMm = 2.5;  // its text
std::string match_caption_text(const MatchCaption& caption);

// Where laying starts, drawn just outside the origin corner: a dot 3 mm out, arrows 14 mm
// along the first row and up the rows, and the words beyond the first arrow (paper mm). No
// label is placed on it.
inline constexpr double kStartDotMm = 3, kStartArrowMm = 14, kStartTextMm = 2;
inline constexpr const char* kStartText = "start: row 0, column 0";

// A coursed set (layout.installer_set): drawn at 1 : 20 unless named, for units at most
// 300 mm long when left automatic.
inline constexpr double kCoursedScale = 20;
inline constexpr double kSmallUnitMm = 300;

// The most installer's sheets a named installer_scale may make (a set a trade can carry).
inline constexpr size_t kMostInstallerSheets = 500;

struct InstallerPlan {
  PaperSheet paper;
  bool coursed = false;  // pieces in colour and hatch, no IDs: `labels` is empty
  bool landscape = true;
  double scale = 1;                      // 1 : scale
  double text_mm = kInstallerTextMm;     // the IDs' text height on paper
  std::array<double, 2> viewport{0, 0};  // the drawing's frame on paper, mm
  size_t grid_columns = 0, grid_rows = 0;
  std::vector<double> column_edges, row_edges;  // where the sheets meet, layout mm, with the ends
  std::vector<InstallerSheet> sheets;           // row by row from the bottom
  std::vector<InstallerPiece> pieces;           // installer_pieces(layout)
  std::vector<InstallerLabel> labels;           // one per piece
  std::vector<MatchCaption> captions;           // both sides of every edge two sheets share
  std::vector<Rect> start_corner;  // what the start corner covers, layout mm (none: blocks)
  size_t unplaced = 0;             // labels that found no free place (drawn at the centre)
  size_t over_labels = 0;          // crowded labels: their leaders may run over other labels
};

// The sheet whose window holds a point (each window holds its left and bottom edges): the
// sheet a piece, its label and its count in the key belong to, by the piece's centre.
size_t sheet_holding(const InstallerPlan& plan, double x, double y);

// The fabrication sheets of a perforated surface, else the elements as laid, in layout order.
std::vector<InstallerPiece> installer_pieces(const Layout& layout);

// The installer's sheets on layout.installer_paper (else layout.paper) at
// layout.installer_scale; unnamed, a coursed set is drawn at 1 : 20 and a labelled one at the
// largest scale where every label finds room.
InstallerPlan plan_installer_sheets(const Layout& layout);

// The sheet numbers of the drawing set: sheet 1 is the whole layout, the installer's sheets
// follow from 2.
inline size_t installer_sheet_number(size_t index) { return index + 2; }

// The frame of the drawing on an installer's sheet of `paper`: its drawing area less a strip
// for row numbers on the left and column numbers along the bottom; a coursed set's also less
// the gauge rod's strip on the right and the dimensions' under the column numbers.
std::array<double, 2> installer_viewport(const PaperSheet& paper, bool landscape,
                                         bool coursed = false);

}  // namespace curdle
