// A surface read from the architect's drawing: the outline, openings and zones on the layers the
// recipe names ([layout.site]), in millimetres from the layout's datum, their arcs kept. The
// drawing's own units are honoured and checked for plausibility, so that a drawing in metres
// read as millimetres (or the reverse) is refused instead of laid 1000 times too small.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "layout/contour.h"
#include "site/drawing.h"

namespace curdle::site {

struct ZoneLayer {
  std::string layer;
  ZoneRule rule = ZoneRule::exclude;
  uint32_t value = 0;
  // Only the layer's shape around this point (drawing coordinates), as an outline is picked;
  // none: every shape on the layer.
  std::optional<std::array<double, 2>> around;
};

// Which of a layer's closed shapes is the outline, where it holds more than one.
struct OutlinePick {
  std::optional<std::array<double, 2>> around;  // the smallest shape around this point
  std::string handle;                           // the shape its entity (or INSERT) draws
  bool largest = false;
};

// [layout.site]: which layers hold what, and how the drawing's units and origin are taken.
struct LayerMap {
  std::string file;  // as the recipe names it, for messages
  std::string outline;
  OutlinePick pick;
  std::vector<std::string> openings;
  std::vector<ZoneLayer> zones;
  double unit_mm = 0;     // the recipe's units; 0: as the drawing says
  std::string unit_name;  // "mm", "cm", "m", "in", "ft"
  // Where the layout's datum (0, 0) lies, in drawing units; absent: the drawing's origin when the
  // outline lies in its first quadrant within 10 km, else the outline's bottom-left corner.
  std::optional<std::array<double, 2>> origin;
  bool origin_at_outline = false;  // origin = "outline"
  double chord_tolerance = 0.05;   // mm, for flattened curves
};

struct SiteZone {
  std::string name;  // the layer's name, numbered where it holds several
  ZoneRule rule = ZoneRule::exclude;
  uint32_t value = 0;
  Contour contour;
};

struct Site {
  Contour outline;                // counter-clockwise, mm from the datum
  std::vector<Contour> openings;  // counter-clockwise
  std::vector<SiteZone> zones;
  std::array<double, 2> datum{0, 0};  // the datum in the drawing, mm from its origin
  double unit_mm = 1;                 // millimetres per drawing unit, as read
  std::string unit_name;              // "m", "mm", ...
  int precision = 4;                  // decimals of the drawing's coordinates
  double height_mm = 0;               // a massing model's node: how high it stands
  std::string summary;                // "outline 14,000 x 9,000 mm with 1 arc; ..."
  std::vector<std::string> notes;     // layers passed over, hidden layers, flattened curves
};

// The drawing in `bytes`, read as its name's ending says: ".svg" (any case) by svg_reader.h,
// anything else by dxf_reader.h. InputError as they throw it.
Drawing read_drawing(std::string_view bytes, const std::string& name, double chord_tolerance_mm,
                     double unit_mm);

// Millimetres per unit for "mm", "cm", "dm", "m", "in" or "ft"; 0 for anything else.
double unit_mm(const std::string& name);

// Throws InputError naming the file, the layer and the entity's handle for: a layer named with
// nothing on it, an open outline (with the gap's ends), a self-intersecting outline (with the
// crossing), an opening or zone outside the outline, a unitless drawing the recipe gives no
// units for, and a drawing whose size in its units is no plausible surface.
Site site_from(const Drawing& drawing, const LayerMap& map);

// How far apart two ends may lie and still be joined into one outline, mm.
inline constexpr double kJoinTolerance = 0.5;

// The closed regions a layer's linework forms, in drawing units, as the outline's pick sees them
// (the outer shapes, pieces joined end to end): what a page shows to pick one by a click.
// `unit_mm` millimetres per drawing unit. Empty when the layer forms none or cannot be read.
std::vector<Contour> closed_regions(const Drawing& drawing, const std::string& layer,
                                    double unit_mm);

}  // namespace curdle::site
