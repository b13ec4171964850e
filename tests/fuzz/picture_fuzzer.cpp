// Fuzz target: the picture gate (export/picture_gate.h) reading any bytes as a picture's file.
// It may refuse them; it may never crash, hang or read past them.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "export/picture_gate.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string why;
  const auto header =
      curdle::read_picture_header(std::string_view(reinterpret_cast<const char*>(data), size), why);
  (void)header;
  return 0;
}
