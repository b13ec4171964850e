#include "app/zone_in_cells.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "curdle/curdling.h"
#include "curdle/error.h"
#include "layout/builder.h"
#include "layout/piece.h"

namespace curdle::app {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

std::string zone_in_cells(const std::string& target, const Run& run) {
  if (target.rfind("empty", 0) != 0 || !ends_with(target, "mm")) return target;
  const size_t equals = target.find('=');
  auto fail = [&](const std::string& what) {  // throws: nothing after it runs
    throw InputError(parameter("target"), "'" + target + "': " + what);
  };
  if (equals == std::string::npos) fail("write empty[:CURD]=X,Y,W,H mm");
  const std::optional<LayoutSpec>& spec = run.recipe.layout;
  if (!spec || !spec->size || !spec->kind->takes_zones())
    fail(
        "a zone in mm needs a tile, paving or facade [layout] with its floor or wall size; "
        "give the zone in cells");
  // X,Y,W,H in mm from the surface's bottom-left corner.
  std::string numbers = target.substr(equals + 1, target.size() - equals - 3);
  while (!numbers.empty() && numbers.back() == ' ') numbers.pop_back();  // "900 mm" too
  std::array<double, 4> v{};
  for (size_t i = 0; i < 4; ++i) {
    const size_t comma = numbers.find(',');
    const std::string item = numbers.substr(0, comma);
    char* end = nullptr;
    v[i] = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(v[i]) || (i >= 2 && v[i] <= 0) ||
        (comma == std::string::npos) != (i == 3))
      fail("write empty[:CURD]=X,Y,W,H mm: four finite numbers, W and H above 0");
    numbers = comma == std::string::npos ? "" : numbers.substr(comma + 1);
  }
  const Rect zone{v[0], v[1], v[2], v[3]};
  const std::array<double, 2>& surface = *spec->size;
  if (zone.x < 0 || zone.y < 0 || zone.right() > surface[0] + 1e-6 ||
      zone.top() > surface[1] + 1e-6)
    fail(fmt::format("the rectangle must lie on the {:g} x {:g} mm surface, from 0, 0", surface[0],
                     surface[1]));
  // The elements' places do not depend on the curds: lay out the floor once, from any field.
  Design design = run.recipe.design;
  const auto cells = elements_to_cover(*spec);
  design.field.size = {cells[0], cells[1], 1};
  const Box floor{{0, 0, 0}, {cells[0], cells[1], 1}};
  const Layout layout = make_layout(design, curdle(design, 0, floor), floor, *spec);
  int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
  for (const Element& e : layout.elements)
    if (overlaps(laid_bounds(e), zone))
      x0 = std::min(x0, e.cell_x), y0 = std::min(y0, e.cell_y), x1 = std::max(x1, e.cell_x),
      y1 = std::max(y1, e.cell_y);
  if (x0 == INT64_MAX)
    fail(fmt::format("no element is laid in that rectangle of the {:g} x {:g} mm surface",
                     layout.width, layout.height));
  return fmt::format("{}={},{},{},{}", target.substr(0, equals), x0, y0, x1 - x0 + 1, y1 - y0 + 1);
}

}  // namespace curdle::app
