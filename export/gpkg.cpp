#include "export/gpkg.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>

#include "curdle/error.h"
#include "export/gis_features.h"
#include "export/module_loader.h"

namespace curdle {
namespace {

// What the module says of a write: 0 written, 1 a CRS the recipe names that will not do (the
// user's to mend), 2 GDAL failed.
using WriteFn = int (*)(const char* path, const GisDataset* data, std::string* error);

WriteFn module(std::string* failure) {
  static WriteFn write = nullptr;
  static std::string why;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle = load_curdle_module(CURDLE_GPKG_MODULE_NAME, &why);
    if (!handle) {
      why +=
          "; it is built where GDAL's development files are (Debian: libgdal-dev, which "
          "setup.sh installs)";
      return;
    }
    write = reinterpret_cast<WriteFn>(::dlsym(handle, "curdle_gpkg_write"));
    if (!write) why = "the GeoPackage module " CURDLE_GPKG_MODULE_NAME " lacks its entry point";
  });
  if (failure) *failure = why;
  return write;
}

}  // namespace

bool gpkg_installed(std::string* why) { return module(why) != nullptr; }

void write_layout_gpkg(const std::filesystem::path& path, const Layout& layout) {
  std::string why;
  const WriteFn write = module(&why);
  if (!write) throw std::runtime_error("cannot write layout.gpkg: " + why);
  // A sink may hand over an empty file it made to hold the name (mkstemp); GDAL creates the
  // GeoPackage itself and will not write over a file.
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec) && std::filesystem::file_size(path, ec) == 0)
    std::filesystem::remove(path, ec);
  const GisDataset data = gis_features(layout);
  std::string error;
  const int result = write(path.c_str(), &data, &error);
  if (result == 1) {
    SourceLocation where;
    where.key = "layout.georef.epsg";
    throw InputError(where, error);
  }
  if (result != 0) throw std::runtime_error("cannot write layout.gpkg: " + error);
}

}  // namespace curdle
