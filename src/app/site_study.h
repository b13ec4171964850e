// A site drawing sent as bytes (the page's upload): its layers, and once the layers are chosen,
// the surface read from it as the recipe keys the page sends with every request (the outline
// with its arcs as bulges, a façade's windows, the zones), as [layout.site] would read it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/run.h"

namespace curdle::app {

struct SiteStudyRequest {
  std::string bytes;    // the drawing's file, as sent
  std::string name;     // its file name: .dxf or .svg
  std::string outline;  // the outline's layer; empty: only list the layers
  // "x,y" in the drawing's coordinates: the outline is the layer's smallest region around this
  // point (the page's click); empty: the layer's one closed shape.
  std::string around;
  std::vector<std::string> openings;  // layers of openings
  std::vector<std::string> zones;     // layers of zones kept free
  std::string units;                  // "mm", "cm", "m", "in", "ft"; empty: as the drawing says
};

// {"file", "format", "units", "layers": [{"name", "shapes", "closed"}], "hidden", "notes",
// "regions": [{"layer", "rings": [[[x, y], ...], ...]}] (each layer's closed regions in drawing
// coordinates, thinned for the page's picture, at most kMostRegionPoints points in all)}, and
// with an outline chosen "site": {"summary", "notes", "sets": ["layout.outline=...", ...],
// "zones": [{"name", "rule", "polygon"}]}. InputError (parameter "name", "outline", ...) for a
// drawing that cannot be read or used, or a run whose layout takes no outline.
inline constexpr size_t kMostRegionPoints = 100000;

nlohmann::ordered_json study_site(const Run& run, const SiteStudyRequest& request);

}  // namespace curdle::app
