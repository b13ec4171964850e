// layout.ifc's building (a layout with frames, src/building): each unit an
// IfcBuildingElementPart placed in 3-D on its façade (a corner unit one prism cut to its corner, a
// unit of a curved wall a chord), each façade an IfcWall that nests its units, each opening
// an IfcOpeningElement voiding its wall and filled by an IfcWindow or IfcDoor. ifc.cpp writes
// the rest of the model (context, storeys, sets) as for any layout.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "export/ifc/ifc_geometry.h"
#include "export/ifc/step_file.h"
#include "layout/framed_corner.h"
#include "layout/layout.h"

namespace curdle {

class IfcEnvelopeWriter {
 public:
  // `root(what)`: a rooted entity's GlobalId and owner history for `what`.
  IfcEnvelopeWriter(StepWriter& w, IfcGeometryWriter& g, const Layout& layout,
                    std::function<StepRoot(std::string_view)> root);

  // A unit's placement (relative to `container_place`, at its first face's outer corner, along
  // its façade) and its body, in `colour`.
  struct Placed {
    int64_t placement = 0, shape = 0;
  };
  Placed unit(const Element& e, int64_t container_place, const Rgb& colour);
  // A one-brick wall's body: its backing leaf behind the face leaf and the collar joint, the
  // headers' tails bonded into it.
  Placed backing(const SurfaceFrame& f, int64_t container_place);

  // The façade a unit belongs to (an index of the layout's frames): the face holding the
  // middle of its laid face.
  size_t facade_of(const Element& e) const;

  // The walls, each nesting `parts[k]` (façade k's units), their openings, windows and
  // doors; returns what the storeys contain (walls, windows and doors), each with the level
  // its base stands at, mm above the building's base.
  std::vector<std::pair<int64_t, double>> walls(int64_t container_place,
                                                const std::vector<std::vector<int64_t>>& parts);

 private:
  // A placement relative to `container` at strip position (u, v) of `frame`'s outer face, along
  // the façade there, or along the chord to `to` where it is given.
  int64_t placement_on(const SurfaceFrame& frame, double u, double v, int64_t container,
                       double to = -1);

  // A face's rectangle profile and its solid's position, shared by every unit that has them.
  int64_t face_profile(double length, double height);
  // A corner unit's footprint from the unit's origin (plan, mm), shared likewise.
  int64_t corner_profile(const FramedPrism& prism, const std::array<double, 3>& origin);
  int64_t position(const std::array<double, 3>& origin, const std::array<double, 3>& axis,
                   const std::array<double, 3>& ref);

  StepWriter& w_;
  IfcGeometryWriter& g_;
  std::map<std::array<double, 2>, int64_t> profiles_;
  std::map<std::array<double, 9>, int64_t> positions_;
  std::map<std::vector<int64_t>, int64_t> corner_profiles_;
  const Layout& l_;
  std::function<StepRoot(std::string_view)> root_;
};

}  // namespace curdle
