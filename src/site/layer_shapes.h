// A layer's shapes as a designer means them: closed shapes, and open pieces (LINE and ARC chains,
// open polylines) joined end to end; a wide polyline's strip where it joins nothing; shapes inside
// others, lines inside a shape and shapes drawn twice passed over and counted; and the words that
// name a shape and a place in messages.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "layout/contour.h"
#include "site/drawing.h"

namespace curdle::site {

// A closed contour on a layer, with the entities it was made of for messages.
struct Closed {
  Contour path;
  std::string handles;  // "3A, 3B"
  std::string entity;   // of its first shape
  int insert = -1;
  std::vector<const Shape*> shapes;  // what it was made of
};

// What a layer holds that is not one of its shapes, counted for the notes.
struct PassedOver {
  size_t inside = 0;   // closed shapes inside another: a trunk in its pit, a sash in its frame
  size_t pieces = 0;   // lines inside a closed shape: a grille, glazing bars
  size_t repeats = 0;  // a shape drawn twice: a hatch over its boundary
};

// The layer's closed contours in drawing units (see above); `role` ("outline", "zone") and
// `unit_mm` for messages. InputError naming the file, layer and entities for a piece left open
// outside every shape, a shape that could not be read (Shape::fault), or a point beyond reach.
std::vector<Closed> closed_on(const Drawing& drawing, const std::string& layer, double tolerance,
                              const std::string& file, const std::string& role, double unit_mm,
                              PassedOver& passed);

// The notes that say what a layer held besides its shapes.
void note_passed_over(const PassedOver& p, const std::string& layer,
                      std::vector<std::string>& notes);

// The smallest of `shapes` around `point` (drawing coordinates), as CAD's BOUNDARY picks;
// InputError naming the point when none lies around it.
Closed smallest_around(const std::vector<Closed>& shapes, const std::array<double, 2>& point,
                       double tolerance, const std::string& file, const std::string& layer,
                       int precision);

// The contour run the other way (each bulge moved to its edge's other end).
Contour reversed(const Contour& path);
// "LINE 9D in block "PIT" (INSERT 2F)": where a designer finds the shape in CAD.
std::string handle_of(const Shape& s);
// A number at the drawing's precision, without trailing zeros; a point as "(x, y)".
std::string number_text(double v, int precision);
std::string point_text(const ContourVertex& v, int precision);
// 14000 as "14,000"; 2.5 as "2.5".
std::string grouped(double v);

}  // namespace curdle::site
