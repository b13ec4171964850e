// Fuzz target: the picture gate (src/io/picture_gate.h) reading any bytes as a picture's file,
// and a PNG it lets through decoded by the in-process reader (src/io/png_reader.h). Either may
// refuse them; neither may crash, hang or read past them.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "io/picture_gate.h"
#include "io/png_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string why;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const auto header = curdle::read_picture_header(bytes, why);
  // Small pictures only, as a caller bounds them by their header first.
  if (header && header->format == curdle::PictureFormat::png &&
      header->width * header->height <= (int64_t{1} << 16)) {
    try {
      (void)curdle::read_png_luminance(bytes);
    } catch (const std::runtime_error&) {
    }
  }
  return 0;
}
