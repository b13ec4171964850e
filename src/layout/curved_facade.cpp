#include "layout/curved_facade.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "layout/contour.h"
#include "layout/drawing_sheet.h"
#include "layout/layout_kind.h"

namespace curdle {
namespace {

std::string point(const std::array<double, 2>& p) {
  return fmt::format("({}, {})", drawing_mm(p[0]), drawing_mm(p[1]));
}

// A round station spacing (1, 2 or 5 times a power of ten, mm) giving 4 to 10 stations.
double station_step(double chord) {
  for (double decade = 100; decade < 1e8; decade *= 10)
    for (const double m : {1.0, 2.0, 5.0})
      if (chord / (m * decade) <= 10) return m * decade;
  return chord;
}

}  // namespace

ChordFit chord_fit(double r, double l, double j, double depth, bool convex) {
  // The turn from unit to unit: a unit's chord and a joint along the face.
  const double turn = 2 * std::asin(std::min(1.0, l / (2 * r))) + j / r;
  return {r - std::sqrt(r * r - l * l / 4), convex ? j - depth * turn : j + depth * turn};
}

std::vector<CurvedFacade> curved_facades(const Layout& layout, double step) {
  std::vector<CurvedFacade> out;
  for (const SurfaceFrame& f : layout.frames()) {
    if (f.bulge == 0) continue;
    const Arc arc = arc_between({f.from[0], f.from[1], f.bulge}, {f.to[0], f.to[1], 0});
    CurvedFacade c;
    c.frame = &f;
    c.centre = arc.centre, c.from = f.from, c.to = f.to, c.radius = arc.radius;
    c.sweep = arc.sweep * 180 / std::numbers::pi;
    c.chord = std::hypot(f.to[0] - f.from[0], f.to[1] - f.from[1]);
    c.convex = f.bulge > 0;
    const double r = c.radius, l = layout.module_w, j = layout.joint, depth = layout.thickness;
    const bool screen = layout.kind && layout.kind->ground() == Ground::sheet;
    const double inside = c.convex ? r - depth : r;  // a rolled sheet's bend
    const bool fins = layout.kind && layout.kind->stands_off();
    if (fins) {  // plates square to it
      c.unit_chord = l;
      c.units = fmt::format(
          "fins standing square to the arc, {:g} mm off its face, a bay of {:g} mm each", depth, l);
    } else if (screen) {  // sheets rolled to it, their openings in cells of `l`
      c.unit_chord = bent_chord(r, l);
      c.units = fmt::format(
          "sheets rolled to the arc, {:.1f} mm inside radius; their blanks developed at "
          "mid-thickness (punching.csv, sheets/)",
          inside);
    } else if (f.bent) {
      c.unit_chord = bent_chord(r, l);
      c.units = fmt::format(
          "{:g} mm units bent to the arc (as ordered), each over a chord of "
          "{:.1f} mm",
          l, c.unit_chord);
    } else {
      c.unit_chord = l;
      const ChordFit fit = chord_fit(r, l, j, depth, c.convex);
      c.inside = fit.inside, c.joint_back = fit.joint_back;
      c.units = fmt::format(
          "{:g} mm units straight on chords, {:.2f} mm inside the arc at their middle; each "
          "joint {:g} mm at the face, {:.1f} mm at the back ({:g} mm in)",
          l, c.inside, j, c.joint_back, depth);
    }
    const double s = step > 0 ? step : station_step(c.chord);
    const double rise = std::sqrt(std::max(0.0, r * r - c.chord * c.chord / 4));
    for (double d = 0; d < c.chord + 1e-6; d += s)
      c.offsets.push_back(
          {d, std::sqrt(std::max(0.0, r * r - std::pow(d - c.chord / 2, 2))) - rise});
    if (c.chord - c.offsets.back().along > 1e-6) c.offsets.push_back({c.chord, 0});
    c.line = fmt::format(
        "façade {} ({}): radius {} mm at the face, centre {}, from {} to {}, "
        "{:.2f}° ({} mm along the face, chord {} mm)",
        f.name, c.convex ? "convex" : "concave", drawing_mm(r), point(c.centre), point(c.from),
        point(c.to), std::fabs(c.sweep), drawing_mm(f.length), drawing_mm(c.chord));
    c.brief[0] = fmt::format("façade {}: radius {} mm round centre {}", f.name, drawing_mm(r),
                             point(c.centre));
    c.brief[1] = fins     ? fmt::format("fins square to it, {:g} mm off its face", depth)
                 : screen ? fmt::format("sheets rolled to it, {:.1f} mm inside radius", inside)
                 : f.bent ? fmt::format("units bent to it, a chord of {:.1f} mm each", c.unit_chord)
                          : fmt::format("chord {:g} mm a unit; joints {:g} mm face, {:.1f} mm back",
                                        l, j, c.joint_back);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace curdle
