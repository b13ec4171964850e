// The recipe's [layout]: each kind has its own reader, which owns its keys (any other key is
// reported, with a did-you-mean) and checks them against the design.
#pragma once

#include <optional>

#include "layout/layout.h"
#include "recipe/toml_reader.h"

namespace curdle::reading {

// The [layout] table, or std::nullopt when there is none. A fixed floor, wall, sheet or line
// sizes the field when `field_given` is false, and must fit in it when true.
std::optional<LayoutSpec> read_layout(TableReader& top, Design& design, bool field_given);

// Keys every kind takes: the schedules' ordering and the drawing's colours and scale.
void read_ordering(TableReader& r, LayoutSpec& spec);
void read_value_colours(TableReader& r, const Design& design, LayoutSpec& spec);
void read_drawing_scale(TableReader& r, LayoutSpec& spec);

// The kinds' own keys, each in its own file.
void read_facade(TableReader& r, LayoutSpec& spec);
// layout.outline (tile, paving, facade): the surface as a polygon; its bounding rectangle is
// the size when the size key is left out.
void read_outline(TableReader& r, LayoutSpec& spec);
// [[layout.zones]], after the surface's size (tile, paving, facade).
void read_zones(TableReader& r, const Design& design, LayoutSpec& spec);
void read_perforation(TableReader& r, const Design& design, LayoutSpec& spec);
void read_park(TableReader& r, const Design& design, LayoutSpec& spec);
void read_rhythm(TableReader& r, Design& design, LayoutSpec& spec, bool field_given);
void read_blocks(TableReader& r, LayoutSpec& spec);

}  // namespace curdle::reading
