#include <charconv>

#include "curdle/error.h"
#include "recipe/recipe.h"

namespace curdle {

Box parse_window(const std::string& text, const Design& design) {
  const int E = design.lattice.dimension;
  const char* form = E == 1 ? "X,W" : E == 2 ? "X,Y,W,H" : "X,Y,Z,W,H,D";
  std::vector<int64_t> v;
  for (size_t start = 0; start <= text.size();) {
    size_t comma = text.find(',', start);
    if (comma == std::string::npos) comma = text.size();
    int64_t x = 0;
    auto [p, ec] = std::from_chars(text.data() + start, text.data() + comma, x);
    if (ec != std::errc() || p != text.data() + comma)
      throw InputError(parameter("window"),
                       "'" + text + "' is not " + form + " (whole numbers of cells)");
    v.push_back(x);
    start = comma + 1;
  }
  if (static_cast<int>(v.size()) != 2 * E)
    throw InputError(parameter("window"), "a " + std::to_string(E) + "-D lattice takes a window " +
                                              form + ", not '" + text + "'");
  Box box;
  for (int d = 0; d < E; ++d) {
    box.origin[d] = v[d];
    box.size[d] = v[E + d];
  }
  if (!box.well_formed() || !design.field.contains(box)) {
    std::string field;
    for (int d = 0; d < E; ++d) field += (d ? " x " : "") + std::to_string(design.field.size[d]);
    throw InputError(parameter("window"), "'" + text + "' must lie inside the field of " + field +
                                              " cells (origin >= 0, sizes >= 1)");
  }
  return box;
}

}  // namespace curdle
