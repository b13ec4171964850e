// A building as the recipe gives it ([layout.building]): a closed plan, or the path of a
// free-standing wall, its height, base and unit depth, and the openings of each façade (listed,
// or by a rule); and its envelope: the façades unrolled into one strip from the start corner,
// whole courses high, with every opening placed on the strip and checked.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "layout/layout.h"
#include "layout/surface_frame.h"

namespace curdle {

// An opening of one façade, in the façade's own unrolled millimetres (x along it from its
// start, y up from the base), the façade by its name ("S", "E2") or its plan edge's index.
struct BuildingOpening {
  std::string facade;
  Rect rect;
  std::string type = "window";  // "window" or "door"
  std::string replaces;         // a window of the rule this one stands in place of ("W-5")
};

// Windows by rule: `size` every `every` mm along each façade, each storey, clear of the
// corners by `clear` mm (the run centred, so both ends clear alike), the sill `sill` mm above
// each storey's floor.
struct WindowRule {
  std::array<double, 2> size{0, 0};
  double every = 0, clear = 0, sill = 0;
  std::vector<std::string> omit;  // the rule's windows left out, by name ("W-3")
};

struct BuildingKeys {
  Contour plan;              // closed (a building), or
  Contour path;              // open (a free-standing wall)
  std::string site_summary;  // where a drawn plan was read from, for the report
  size_t start = 0;
  // The field column at the strip's start, round a closed envelope (strip_ring.h); absent: the
  // phase that keeps the corners off the coarse stages' boundaries.
  std::optional<int64_t> phase;
  double height = 0;            // mm, whole courses: the tallest façade's
  std::vector<double> heights;  // per plan edge where they differ, each at most `height`
  double storey = 0;            // floor to floor, mm; 0: one storey the wall's height
  std::vector<double> storeys;  // each storey's floor to floor from the base, where they differ
  double base = 0;              // the datum's level, mm
  double depth = 0;  // the unit's depth into the wall, mm; 0: half a unit less half a joint
  bool coursed_openings = true;  // sills and heads moved onto course lines
  bool bent_on_arcs = false;     // units on an arc bent to it (cladding), not straight on chords
  // What the wall is: "half-brick" (a leaf, the face alone: its headers snap headers), "cavity"
  // (a cavity wall's outer leaf, likewise), or "one-brick" (a solid wall a unit's length thick:
  // headers run through, and a backing unit of `backing` stands behind every other face unit).
  std::string wall = "half-brick";
  std::string backing = "Common brick";
  std::vector<BuildingOpening> openings;
  std::optional<WindowRule> windows;
};

// The most units an envelope may hold: a bigger one is refused before it is laid.
inline constexpr double kMostEnvelopeUnits = 500000;

struct Envelope {
  std::vector<SurfaceFrame> facades;
  bool closed = true;   // round a building, or along a free-standing wall
  double length = 0;    // the strip, mm
  double height = 0;    // mm
  double depth = 0;     // the unit's depth, mm
  bool solid = false;   // a one-brick wall: backing units behind the face (BuildingKeys::wall)
  std::string backing;  // their material
  int64_t courses = 0;
  std::vector<Rect> openings;          // on the strip, mm
  std::vector<size_t> opening_facade;  // each opening's façade (an index of `facades`)
  std::vector<std::string> opening_type;
  std::vector<std::string> opening_names;  // "W-12", "D-1": as every output names them
  std::vector<std::string> notes;          // what was moved onto courses, and why
};

// The envelope of `keys` for units of the spec's size and joint. Throws InputError (keys under
// layout.building) for heights that are not whole courses (naming the nearest that are), plans
// that cross themselves, façades shorter than a unit, openings that overlap, cross a corner or
// the top, or name no façade, and envelopes of more than kMostEnvelopeUnits units.
Envelope envelope_of(const BuildingKeys& keys, const LayoutSpec& spec);

// The façade an opening names: its name ("S", "E2", case as given) or its plan edge's index.
const SurfaceFrame* facade_named(const std::vector<SurfaceFrame>& facades, const std::string& name);

}  // namespace curdle
