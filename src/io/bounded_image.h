// Reading a picture a user names, as hostile input: a regular file (never a device or a pipe)
// of at most 64 MiB, whose decoded size, read from its header first, fits the memory limit.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "curdle/error.h"
#include "io/image.h"

namespace curdle {

// `what` names the picture in messages ("the mask image"), followed by `shown` (default: the
// path; a temporary file holding an upload is shown by the upload's name). Throws InputError at
// `where` when the file is missing, not a regular file, too large or unreadable, and
// ResourceLimitError when decoding it would take more than `max_bytes` or it has over `max_pixels`
// pixels.
LuminanceImage read_bounded_luminance(const std::filesystem::path& path, const std::string& what,
                                      const SourceLocation& where, uint64_t max_bytes,
                                      uint64_t max_pixels = uint64_t{1} << 32,
                                      const std::string& shown = {},
                                      int64_t max_side = int64_t{1} << 31);

}  // namespace curdle
