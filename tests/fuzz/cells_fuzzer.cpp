// Fuzz target: a cells.csv read back (curdle fit's input). Input: the file's text. It may be
// refused with an InputError or a ResourceLimitError; it may never crash, hang or allocate
// beyond the box it is allowed.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "curdle/error.h"
#include "io/cells_csv_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 1 << 20) return 0;
  try {
    const curdle::CellsTable t = curdle::parse_cells_csv(
        std::string_view(reinterpret_cast<const char*>(data), size), 1 << 16);
    (void)t;
  } catch (const curdle::InputError&) {  // ResourceLimitError too
  }
  return 0;
}
