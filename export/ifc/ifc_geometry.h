// The geometry of layout.ifc, written into its STEP file: profiles in a surface's plane (a
// rectangle, a polygon with islands, several parts as one composite profile, a sheet with its
// holes as voids), each extruded as one solid in its colour. Profile points are relative to
// the product being written, which is placed at its own corner (ifc.cpp), as BIM tools expect
// of every element; 3-D points and directions are absolute.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "export/ifc/step_file.h"
#include "layout/contour.h"
#include "layout/layout.h"

namespace curdle {

class IfcGeometryWriter {
 public:
  // `chord_tolerance`: how far a circle's polygon may stray inside it, mm (the layout's).
  IfcGeometryWriter(StepWriter& w, double chord_tolerance);

  int64_t world() const { return world_; }  // the identity placement
  // The representation context solids are drawn in (the model's 'Body' subcontext).
  void set_body_context(int64_t body) { body_ = body; }
  // The corner of the product being written: its profiles are drawn from there.
  void set_local_origin(double x, double y) { local_ = {x, y}; }

  int64_t point(double x, double y, double z);
  int64_t direction(double x, double y, double z);
  // A closed polyline through the ring's points, relative to the local origin.
  int64_t polyline(const Ring& ring);
  // The same as one list of coordinates (IfcIndexedPolyCurve through IfcCartesianPointList2D):
  // a sheet's thousands of holes as a point entity for each of their corners were most of a
  // perforated screen's IFC.
  int64_t point_list_curve(const Ring& ring);
  // A contour as an IfcIndexedPolyCurve in the surface's own coordinates: straight edges as
  // IfcLineIndex, arcs as IfcArcIndex through their middle, so that a reader draws the true arc
  // rather than its chords.
  int64_t contour_curve(const Contour& contour);
  // A polyline written once for every ring of that shape from its local origin (to a
  // nanometre): the openings of a screen, each placed at its own corner, share a few outlines.
  int64_t shared_polyline(const Ring& ring);

  // Profiles.
  int64_t rectangle(const Rect& r);
  int64_t circle(const Circle& c);
  // One part: its outer ring, and its islands as voids.
  int64_t part_profile(const Outline& part);
  // A piece in any number of parts as one profile: a composite profile when there are several.
  int64_t profile(const std::vector<Outline>& parts);
  // An outer ring less `holes` (a sheet and the openings punched in it).
  int64_t profile_with_holes(const Ring& outer, const std::vector<Ring>& holes);

  // A solid from `base` to `base + depth` out of the profile's plane, in `colour`.
  int64_t solid(int64_t profile, double base, double depth, const Rgb& colour);
  // A solid of `depth` along the z of `position` (an IfcAxis2Placement3D in the product's
  // frame), for pieces whose faces do not all lie in the product's plane (a corner unit).
  int64_t solid_placed(int64_t profile, int64_t position, double depth, const Rgb& colour);
  // An IfcAxis2Placement3D at `origin`, its z `axis` and x `ref`.
  int64_t axes(const std::array<double, 3>& origin, const std::array<double, 3>& axis,
               const std::array<double, 3>& ref);
  // The product's shape: a 'Body' representation of `items`.
  int64_t body(const std::vector<int64_t>& items);
  // A surface given by its triangles (3-D points, mm; corners counter-clockwise seen from
  // outside), in its colour: a sheet rolled to an arc, which no extrusion draws, or a tile of
  // it; the solid is their sum.
  int64_t triangles(const std::vector<std::array<double, 3>>& points,
                    const std::vector<uint32_t>& indices, const Rgb& colour);
  // A shape drawn once and placed many times (a screen's tiles): its map, and a copy of it
  // moved to `origin` (absolute, mm) with its x, y and z along `x`, up and `x` x up.
  int64_t representation_map(int64_t item);
  int64_t mapped(int64_t map, const std::array<double, 3>& origin, const std::array<double, 2>& x);
  int64_t mapped_body(const std::vector<int64_t>& items);

 private:
  int64_t point(double x, double y);
  // An IfcCartesianPointList2D of the points as they are given.
  int64_t point_list(const std::vector<std::array<double, 2>>& points);
  int64_t base_placement(double base);
  int64_t style(const Rgb& c);

  StepWriter& w_;
  double chord_tolerance_;
  std::array<double, 2> local_{0, 0};
  int64_t z_ = 0, world_ = 0, body_ = 0;
  std::map<double, int64_t> bases_;
  std::map<std::array<double, 3>, int64_t> directions_;  // axes' directions, written once each
  std::map<uint32_t, int64_t> styles_;
  std::map<std::vector<std::array<int64_t, 2>>, int64_t> shared_polylines_;
};

// A circle as a polygon within `chord_tolerance`, as the DXF and glTF draw it, with corners at
// its four extremes so that its extent is the circle's in every reader (readers tessellate
// IfcCircleProfileDef each their own way: web-ifc's missed by 0.3 mm). Counter-clockwise.
Ring ifc_circle_ring(const Circle& c, double chord_tolerance);

}  // namespace curdle
