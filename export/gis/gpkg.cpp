#include "export/gis/gpkg.h"

#include <dlfcn.h>

#include <future>
#include <mutex>
#include <stdexcept>

#include "curdle/error.h"
#include "export/gis/gis_features.h"
#include "io/module_loader.h"

namespace curdle {
namespace {

// What the module says of a write: 0 written, 1 a CRS the recipe names that will not do (the
// user's to mend), 2 GDAL failed.
using WriteFn = int (*)(const char* path, const GisDataset* data, std::string* error);

constexpr const char* kBuiltWhere =
    "; it is built where GDAL's development files are (Debian: libgdal-dev, which setup.sh "
    "installs)";

struct Loaded {
  WriteFn write = nullptr;
  std::string why;
};

Loaded load() {
  Loaded out;
  void* handle = load_curdle_module(CURDLE_GPKG_MODULE_NAME, &out.why);
  if (!handle) {
    out.why += kBuiltWhere;
    return out;
  }
  out.write = reinterpret_cast<WriteFn>(::dlsym(handle, "curdle_gpkg_write"));
  if (!out.write)
    out.why = "the GeoPackage module " CURDLE_GPKG_MODULE_NAME " lacks its entry point";
  return out;
}

// GDAL and the hundred libraries it maps take a tenth of a second to load: once the module is
// found, it loads on a thread of its own while the curds are laid, and the writer waits for it.
std::shared_future<Loaded>& loading() {
  static std::shared_future<Loaded> loaded;
  return loaded;
}
std::mutex loading_mutex;

std::shared_future<Loaded> start_loading() {
  std::lock_guard lock(loading_mutex);
  if (!loading().valid()) loading() = std::async(std::launch::async, load).share();
  return loading();
}

}  // namespace

bool gpkg_installed(std::string* why) {
  std::string failure;
  if (find_curdle_module(CURDLE_GPKG_MODULE_NAME, &failure).empty()) {
    if (why) *why = failure + kBuiltWhere;
    return false;
  }
  start_loading();
  return true;
}

void write_layout_gpkg(const std::filesystem::path& path, const Layout& layout) {
  const Loaded& loaded = start_loading().get();
  const WriteFn write = loaded.write;
  if (!write) throw InputError("cannot write layout.gpkg: " + loaded.why);
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
  // Writing failed (a full disk, a folder that is no folder): the user's to mend, exit 2 as
  // every other writer's.
  if (result != 0)
    throw InputError("cannot write " + path.string() + ": " + error +
                     " (is the disk full, or the folder not writable?)");
}

}  // namespace curdle
