// Rhythm and blocks: the one- and three-dimensional curds as architecture. A 1-D curd is a
// line of bays (fins, mullions, bays of a colonnade) whose element widths and colours follow
// the values; a 3-D curd is a stack of voxels (blocks), drawn as a plan and an elevation.
#pragma once

#include "curdle/curd.h"
#include "layout/layout.h"

namespace curdle {

// Narrows each bay's element to its value's width, centred in the bay; drops zero widths.
void set_rhythm(Layout& layout, const LayoutSpec& spec);

// The voxels of a 3-D view of the field, with plan and elevation drawings.
Layout stack_blocks(const Design& design, const CurdField& field, const Box& view,
                    const LayoutSpec& spec);

}  // namespace curdle
