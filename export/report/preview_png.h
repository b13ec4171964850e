// preview.png: a colour per value, cells scaled up so they can be seen (or averaged down when
// there are more cells than pixels). 2-D: the view as a plan, y up. 1-D: a strip, wrapped
// into lines. 3-D: a sheet of z-slices, z = 0 first.
#pragma once

#include <filesystem>
#include <functional>

#include "curdle/curd.h"
#include "io/image.h"

namespace curdle {

// Bytes render_preview needs for `view` (its accumulators and the image).
uint64_t preview_memory(const Design& design, const Box& view);

PreviewImage render_preview(const Design& design, const CurdField& field, const Box& view,
                            const std::function<void(double)>& progress = {});

}  // namespace curdle
