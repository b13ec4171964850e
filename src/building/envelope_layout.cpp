#include "building/envelope_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "curdle/stop.h"

namespace curdle {
namespace {
constexpr double kEps = 1e-6;

// A unit's part in its bond, for the order: a header through a solid wall or a snap header in
// a leaf, a queen closer (running as deep as a header), a cut, a stopped end's half unit.
UnitPart part_of(const CourseUnit& u, bool solid, double queen) {
  switch (u.role) {
    case UnitRole::header:
      return solid ? UnitPart::header : UnitPart::snap_header;
    case UnitRole::closer:
      return u.depth > 0 && std::fabs(u.to - u.from - queen) < kEps ? UnitPart::queen_closer
                                                                    : UnitPart::cut;
    case UnitRole::end:
      return UnitPart::half_bat;
    default:
      return UnitPart::whole;
  }
}
}  // namespace

void lay_envelope(Layout& layout, const Envelope& env, const Coursing& coursing,
                  const std::vector<uint16_t>& values, const LayoutSpec& spec,
                  const std::optional<StripRing>& ring) {
  const double pitch_w = spec.module_w + spec.joint, pitch_h = spec.module_h + spec.joint;
  // Above a façade lower than the wall: no units, drawn as paper.
  for (const SurfaceFrame& f : env.facades)
    if (f.height > 0)
      layout.outside.push_back(Rect{f.start, f.height, f.length, env.height - f.height});
  const std::vector<Rect> holes = layout.holes();
  const Box& view = layout.view;
  const int digits = static_cast<int>(std::to_string(std::max(layout.columns, layout.rows)).size());
  layout.elements.clear();
  layout.elements.reserve(coursing.units.size());
  layout.omitted = 0;
  EnvelopeFrames& frames = layout.envelope.emplace();
  frames.frames = env.facades;
  frames.closed = env.closed;
  const CourseBond bond = coursing.bond;
  layout.bond = bond == CourseBond::stack     ? 0
                : bond == CourseBond::third   ? 1.0 / 3
                : bond == CourseBond::quarter ? 0.25
                                              : 0.5;
  frames.bond_name = bond == CourseBond::english   ? "English"
                     : bond == CourseBond::flemish ? "Flemish"
                                                   : "";
  frames.opening_kinds = env.opening_type;
  frames.opening_names = env.opening_names;
  const bool solid = env.solid;
  if (solid) frames.backing = WallBacking{env.backing, env.depth + spec.joint};
  int64_t course = -1, column = 0;
  for (const CourseUnit& u : coursing.units) {
    stop_point();
    if (u.course != course) course = u.course, column = 0;
    Element e;
    e.row = u.course;
    e.column = column++;
    const double middle = wrap_along((u.from + u.to) / 2, env.length);
    const int64_t i =
        ring ? std::min<int64_t>(ring_column(*ring, middle), view.size[0] - 1)
             : std::min<int64_t>(static_cast<int64_t>(middle / pitch_w), view.size[0] - 1);
    const int64_t j = std::min<int64_t>(u.course, view.size[1] - 1);
    e.cell_x = view.origin[0] + i;
    e.cell_y = view.origin[1] + j;
    e.value = values[static_cast<size_t>(j * view.size[0] + i)];
    const double y = static_cast<double>(u.course) * pitch_h;
    e.nominal = Rect{u.from, y, u.to - u.from, spec.module_h};
    e.stock_w = spec.module_w, e.stock_h = spec.module_h;
    e.corner = u.corner;
    e.part = part_of(u, solid, queen_closer(env.depth, spec.joint));
    // In a leaf a header is a snap header, no deeper than the leaf; through a solid wall the
    // units that do not run through stand in front of their backing, a leaf's depth.
    e.depth = solid ? (u.depth > 0 ? u.depth : env.depth) : 0;
    std::vector<Rect> parts{Rect{u.from, y, std::min(u.to, env.length) - u.from, spec.module_h}};
    if (u.to > env.length + kEps) parts.push_back(Rect{0, y, u.to - env.length, spec.module_h});
    for (const Rect& p : parts)
      for (const Rect& r : subtract(p, holes)) e.shape.push_back(r);
    if (e.shape.empty() || e.area() < kEps) {
      ++layout.omitted;  // wholly in an opening
      continue;
    }
    e.cut = u.role == UnitRole::closer || u.role == UnitRole::end ||
            e.area() < (u.to - u.from) * spec.module_h - kEps;
    e.key = ElementId{spec.kind->id_letter(), digits, std::nullopt, e.row, e.column, ""};
    e.id = e.key.text();
    layout.elements.push_back(std::move(e));
  }
  // Writers index pieces by course and column: a course may hold a unit or two more than cells.
  for (const Element& e : layout.elements) layout.columns = std::max(layout.columns, e.column + 1);
  layout.notes.insert(layout.notes.end(), env.notes.begin(), env.notes.end());
  layout.notes.insert(layout.notes.end(), coursing.notes.begin(), coursing.notes.end());
}

std::vector<std::string> corner_grid_notes(const Layout& layout, const Design& design,
                                           const std::optional<StripRing>& ring) {
  std::vector<std::string> out;
  const double pitch_w = layout.module_w + layout.joint;
  const int b = design.lattice.base, stages = design.lattice.stages;
  const auto root = static_cast<int64_t>(design.lattice.root_side());  // in field cells
  // Places in the field's own cells: a window may start the strip anywhere in a larger curd.
  const int64_t origin = layout.view.origin[0];
  auto place = [&](double u) {
    std::string s;
    const double cell = ring ? std::fmod(u / ring->cell + static_cast<double>(ring->phase),
                                         static_cast<double>(ring->columns))
                             : static_cast<double>(origin) + u / pitch_w;
    for (int64_t size = root / b, k = 1; k <= stages; ++k, size /= b) {
      const double within = std::fmod(cell, static_cast<double>(size));
      s += fmt::format("{}stage {}: {}", k == 1 ? "" : "; ", k,
                       within < 1e-6 ? std::string("on a boundary")
                                     : fmt::format("{:.2f} of a cell in", within / size));
    }
    return s;
  };
  const bool on_root = origin % root == 0;
  for (const SurfaceFrame& f : layout.frames()) {
    if (f.last_of_path) continue;
    const double u = f.start + f.length;
    const bool closing = layout.envelope->closed && &f == &layout.frames().back();
    std::string seam;
    if (closing && ring)
      seam = ", the closing corner: the field wraps round, its last cell beside its first";
    else if (closing)
      seam = on_root ? ", the closing seam: the strip begins on a root-cell boundary, so its "
                       "start and end meet as two root cells do"
                     : fmt::format(
                           ", the closing seam: the strip begins at cell {}, inside a "
                           "root cell of {}; a window from a multiple of {} starts it "
                           "on a boundary",
                           origin, root, root);
    out.push_back(fmt::format("corner at the end of {} ({:.1f} mm along the strip{}): {}", f.name,
                              u, seam, place(u)));
  }
  return out;
}

}  // namespace curdle
