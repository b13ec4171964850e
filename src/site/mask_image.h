// A façade mask: an image laid over the wall whose dark pixels (luminance below one half) are
// openings. Read through OpenImageIO and turned into opening rectangles in millimetres.
#pragma once

#include <filesystem>
#include <vector>

#include "curdle/error.h"
#include "layout/layout.h"

namespace curdle {

// Throws InputError at `where` (the recipe and its key) when the image is not a regular file
// of at most 64 MiB or cannot be read, and ResourceLimitError when decoding it would take more
// than `max_bytes` (read from its header first).
std::vector<Rect> read_mask_openings(const std::filesystem::path& image, double wall_width,
                                     double wall_height, const SourceLocation& where,
                                     uint64_t max_bytes);

}  // namespace curdle
