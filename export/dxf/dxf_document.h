// A DXF drawing in millimetres that CAD programs open at true size: AutoCAD 2007 (AC1021, so
// that its text is UTF-8) with dxflib's entities, $INSUNITS = 4 (mm), metric measurement and
// the drawing's extents in the header, one layer per material (true colour), closed polylines, and
// layers that do not plot.
#pragma once

#include <dxflib/dl_dxf.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "export/dxf/dxf_writer.h"
#include "layout/layout.h"

namespace curdle {

struct DxfLayer {
  std::string name;  // as given; made a valid DXF name by dxf_layer_name
  Rgb colour;
  bool plot = true;  // false: shown on screen, never plotted or cut (IDs, notes)
};

// A valid DXF layer name: characters DXF forbids become '_'; letters in any script are kept,
// in UTF-8 as AutoCAD 2007 writes them.
std::string dxf_layer_name(const std::string& name);
// Text as a DXF TEXT entity holds it: one line (control characters and line breaks become
// spaces, so that no text can write group codes of its own), encoded as layer names are.
std::string dxf_text(const std::string& text);

// The layer of round openings of one diameter, in the layout's DXF and the sheets' alike:
// "HOLE_D22.6", written HOLE_D22_6.
std::string hole_layer(double diameter);

class DxfDocument {
 public:
  // Opens `path` and writes the header and tables; throws InputError when it cannot be written.
  // Coordinates are given in mm from the layout's datum; with a `frame` they are written in the
  // site drawing's own units and coordinates ($INSUNITS its units), so that the file overlays
  // that drawing at (0, 0, 0) with scale 1.
  DxfDocument(const std::filesystem::path& path, const std::vector<DxfLayer>& layers,
              const Rect& extents, const std::optional<SiteFrame>& frame = std::nullopt);
  ~DxfDocument();

  void polygon(const std::string& layer, const Ring& ring);  // a closed polyline
  // A closed polyline whose arcs are bulges, as CAD draws them; a whole circle as a CIRCLE.
  void contour(const std::string& layer, const Contour& contour);
  void rect(const std::string& layer, const Rect& r);
  void circle(const std::string& layer, double cx, double cy, double d);
  void text(const std::string& layer, double x, double y, double height, const std::string& text,
            bool centred);
  void close();  // ends the entities and the file

 private:
  // From the layout's mm to the file's coordinates and lengths.
  double x(double mm) const { return frame_ ? frame_->datum[0] + mm / frame_->unit_mm : mm; }
  double y(double mm) const { return frame_ ? frame_->datum[1] + mm / frame_->unit_mm : mm; }
  double length(double mm) const { return frame_ ? mm / frame_->unit_mm : mm; }

  std::optional<SiteFrame> frame_;
  DL_Dxf dxf_;
  std::unique_ptr<BufferedDxfWriter> dw_;
  std::filesystem::path path_;
  bool closed_ = false;
};

}  // namespace curdle
