// layout.gpkg: the layout as an OGC GeoPackage for QGIS, ArcGIS and any GDAL reader, one
// feature per piece with its schedule attributes and its shape as laid (gis_features.h), a
// layer per kind of element, in the project's CRS with layout.georef. GDAL (and the hundred
// libraries it brings) lives in a module, libcurdle_gpkg.so, loaded when a GeoPackage is
// written; it is built where GDAL's development files are installed.
#pragma once

#include <filesystem>
#include <string>

#include "layout/layout.h"

namespace curdle {

// Whether the GeoPackage module is installed; when not, `why` says what to install. When it is,
// it starts loading in the background, for write_layout_gpkg, which fails with the loader's
// reason if it will not load.
bool gpkg_installed(std::string* why);

// Writes `path` (which must not exist). Throws InputError when layout.georef's EPSG code is not
// a projected CRS in metres GDAL knows, and std::runtime_error when the module is missing or
// GDAL fails.
void write_layout_gpkg(const std::filesystem::path& path, const Layout& layout);

}  // namespace curdle
