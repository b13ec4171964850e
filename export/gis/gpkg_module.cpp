// libcurdle_gpkg.so: the only code that touches GDAL. Loaded on demand by gpkg.cpp.
#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>
#include <ogrsf_frmts.h>  // RegisterOGRGeoPackage: the one driver, not all of GDAL's

#include <memory>
#include <mutex>
#include <string>

#include "export/gis/gis_features.h"

using curdle::GisDataset;
using curdle::GisField;

namespace {

constexpr const char* kUndefinedCartesian = "LOCAL_CS[\"Undefined Cartesian SRS\"]";

struct SrsDeleter {
  void operator()(OGRSpatialReferenceH s) const { OSRDestroySpatialReference(s); }
};
using Srs = std::unique_ptr<std::remove_pointer_t<OGRSpatialReferenceH>, SrsDeleter>;

// The recipe's CRS: a projected one in metres, easting first. Null and `error` set otherwise.
Srs projected_crs(int epsg, std::string* error) {
  Srs srs(OSRNewSpatialReference(nullptr));
  const std::string name = "EPSG:" + std::to_string(epsg);
  if (OSRImportFromEPSG(srs.get(), epsg) != OGRERR_NONE) {
    *error = "must be the EPSG code of a projected CRS GDAL knows; " + name + " is none";
    return nullptr;
  }
  if (!OSRIsProjected(srs.get())) {
    const char* what = OSRIsGeographic(srs.get()) ? "a geographic CRS (it measures in degrees)"
                       : OSRIsGeocentric(srs.get())
                           ? "a geocentric CRS (x, y, z from the earth's centre)"
                       : OSRIsVertical(srs.get()) ? "a vertical CRS (it measures heights)"
                                                  : "not a projected CRS";
    *error = name + " is " + what +
             "; a layout is placed in a projected CRS in metres, e.g. EPSG:25832 (ETRS89 / UTM "
             "32N) or EPSG:27700 (British National Grid)";
    return nullptr;
  }
  if (OSRGetLinearUnits(srs.get(), nullptr) != 1.0) {
    *error = name + " measures in other units than metres; give a projected CRS in metres";
    return nullptr;
  }
  OSRSetAxisMappingStrategy(srs.get(), OAMS_TRADITIONAL_GIS_ORDER);
  return srs;
}

// No georef: the site's own grid, which GeoPackage calls the undefined Cartesian SRS (srs_id -1;
// GDAL maps this name to it). Left without one, a layer is put in the undefined *geographic*
// SRS (srs_id 0), and GDAL and QGIS read its metres as degrees.
Srs undefined_cartesian_crs() {
  Srs srs(OSRNewSpatialReference(nullptr));
  OSRSetFromUserInput(srs.get(), kUndefinedCartesian);
  return srs;
}

OGRFieldType ogr_type(GisField::Type t) {
  switch (t) {
    case GisField::Type::integer:
      return OFTInteger64;
    case GisField::Type::real:
      return OFTReal;
    case GisField::Type::text:
      break;
  }
  return OFTString;
}

OGRGeometryH multipolygon(const curdle::GisFeature& f) {
  OGRGeometryH multi = OGR_G_CreateGeometry(wkbMultiPolygon);
  for (const std::vector<curdle::Ring>& rings : f.polygons) {
    OGRGeometryH polygon = OGR_G_CreateGeometry(wkbPolygon);
    for (const curdle::Ring& ring : rings) {
      OGRGeometryH r = OGR_G_CreateGeometry(wkbLinearRing);
      for (const auto& [x, y] : ring) OGR_G_AddPoint_2D(r, x, y);
      if (!ring.empty()) OGR_G_AddPoint_2D(r, ring.front()[0], ring.front()[1]);
      OGR_G_AddGeometryDirectly(polygon, r);
    }
    OGR_G_AddGeometryDirectly(multi, polygon);
  }
  return multi;
}

void set_field(OGRFeatureH feature, int index, const curdle::GisValue& value) {
  if (const auto* v = std::get_if<std::int64_t>(&value))
    OGR_F_SetFieldInteger64(feature, index, *v);
  else if (const auto* d = std::get_if<double>(&value))
    OGR_F_SetFieldDouble(feature, index, *d);
  else if (const auto* t = std::get_if<std::string>(&value))
    OGR_F_SetFieldString(feature, index, t->c_str());
}

std::string gdal_error(const char* what) {
  const char* message = CPLGetLastErrorMsg();
  return std::string(what) + (message && *message ? std::string(": ") + message : "");
}

int write_layers(GDALDatasetH ds, const GisDataset& data, OGRSpatialReferenceH srs,
                 std::string* error) {
  const std::unique_ptr<char*, decltype(&CSLDestroy)> options(
      CSLSetNameValue(CSLSetNameValue(nullptr, "GEOMETRY_NAME", "geom"), "FID", "fid"), CSLDestroy);
  for (const curdle::GisLayer& l : data.layers) {
    OGRLayerH layer =
        GDALDatasetCreateLayer(ds, l.name.c_str(), srs, wkbMultiPolygon, options.get());
    if (!layer) {
      *error = gdal_error(("cannot create the layer " + l.name).c_str());
      return 2;
    }
    for (const GisField& field : data.fields) {
      OGRFieldDefnH defn = OGR_Fld_Create(field.name.c_str(), ogr_type(field.type));
      OGR_L_CreateField(layer, defn, TRUE);
      OGR_Fld_Destroy(defn);
    }
    for (const curdle::GisFeature& f : l.features) {
      OGRFeatureH feature = OGR_F_Create(OGR_L_GetLayerDefn(layer));
      for (size_t i = 0; i < f.values.size(); ++i)
        set_field(feature, static_cast<int>(i), f.values[i]);
      OGR_F_SetGeometryDirectly(feature, multipolygon(f));
      const OGRErr e = OGR_L_CreateFeature(layer, feature);
      OGR_F_Destroy(feature);
      if (e != OGRERR_NONE) {
        *error = gdal_error(("cannot add a feature to " + l.name).c_str());
        return 2;
      }
    }
  }
  return 0;
}

// 0 written, 1 a CRS the recipe names that will not do, 2 GDAL failed (gpkg.cpp's WriteFn).
int write_dataset(const char* path, const GisDataset& data, std::string* error) {
  Srs srs;
  if (data.epsg) {
    srs = projected_crs(data.epsg, error);
    if (!srs) return 1;
  } else {
    srs = undefined_cartesian_crs();
  }
  GDALDriverH driver = GDALGetDriverByName("GPKG");
  if (!driver) {
    *error = "GDAL has no GeoPackage driver";
    return 2;
  }
  GDALDatasetH ds = GDALCreate(driver, path, 0, 0, 0, GDT_Unknown, nullptr);
  if (!ds) {
    *error = gdal_error("cannot create the GeoPackage");
    return 2;
  }
  // One transaction: a feature per insert would sync the file thousands of times.
  GDALDatasetStartTransaction(ds, FALSE);
  int result = write_layers(ds, data, srs.get(), error);
  if (result == 0 && GDALDatasetCommitTransaction(ds) != OGRERR_NONE) {
    *error = gdal_error("cannot commit the GeoPackage");
    result = 2;
  }
  GDALClose(ds);
  return result;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int curdle_gpkg_write(const char* path,
                                                                        const GisDataset* data,
                                                                        std::string* error) {
  static std::once_flag registered;
  std::call_once(registered, [] { RegisterOGRGeoPackage(); });
  // GDAL's messages become the error curdle reports, not lines of their own on the terminal.
  CPLPushErrorHandler(CPLQuietErrorHandler);
  // The same run gives the same bytes: the time stamps a GeoPackage keeps are fixed, as the
  // other outputs' are.
  CPLSetThreadLocalConfigOption("OGR_CURRENT_DATE", "2000-01-01T00:00:00.000Z");
  const int result = write_dataset(path, *data, error);
  CPLSetThreadLocalConfigOption("OGR_CURRENT_DATE", nullptr);
  CPLPopErrorHandler();
  return result;
}
