// Building a layout from generated curds: one element per cell of the view, placed on a grid
// of modules and joints from the origin corner, cut at the edges of the floor or wall and
// around openings.
#pragma once

#include <array>

#include "curdle/curd.h"
#include "layout/layout.h"

namespace curdle {

// Elements along x and y that cover the spec's floor or wall: those that start inside it, in
// every course of the bond.
std::array<int64_t, 2> elements_to_cover(const LayoutSpec& spec);

// How far course `row` (counted from the origin corner) is moved back along x by the bond, mm.
double course_offset(const LayoutSpec& spec, int64_t row);
double course_offset(double bond, double pitch, int64_t row);
// The most any of `rows` courses is moved back by the bond.
double largest_offset(const LayoutSpec& spec, int64_t rows);

// The shift that centres the grid on a surface of `extent` mm along one axis: the cut pieces
// at both ends equal (0 when whole elements fill it).
double centring_shift(double extent, double module, double joint);

// Elements x corners of sloping or curved edges that cutting may test: about ten seconds (90,000
// elements along a 10,000-corner ellipse, 9e8, took 35 s).
inline constexpr uint64_t kMaxCuttingWork = uint64_t{1} << 28;

// The surface a grid is laid on, without its elements: the layout's size and settings from the
// spec and the openings and excluded zones on it (a building's strip, whose units are coursed
// round its corners instead).
Layout lay_surface(const Box& view, const LayoutSpec& spec, const std::vector<Rect>& openings);

// A grid of modules and joints laid from the origin corner over `view` (a 2-D box of cells),
// one element per cell, cut at the surface's edges, its outline, `openings` (a façade's windows
// and doors) and excluded zones; value zones applied. For kinds to build on.
Layout lay_grid(const Design& design, const CurdField& field, const Box& view,
                const LayoutSpec& spec, const std::vector<Rect>& openings);
// The grid of a spec with a fixed size over its whole surface, every element of value 0: its
// pieces and cuts without a curd, to test a shift before it is advised. What the outline cuts
// away (Layout::cut_away, drawn but never counted) is left out: it is the real layout's.
Layout lay_blank_grid(const LayoutSpec& spec, const std::vector<Rect>& openings);
// The notes on the lattice's first stage, the legend and its counts of the elements laid.
void count_values(Layout& layout, const Design& design, const LayoutSpec& spec);

// The layout of `view` by the spec's kind, with its provenance (recipe, description, the
// field's seed, lattice and curds). A fixed floor, wall, sheet or line is laid from the view's
// corner, so its view (a segment of a larger curd) must be exactly elements_to_cover cells.
// Throws InputError for specs that cannot be laid.
Layout make_layout(const Design& design, const CurdField& field, const Box& view,
                   const LayoutSpec& spec);

}  // namespace curdle
