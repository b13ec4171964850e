#include "io/image.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>

#include "io/module_loader.h"

namespace fs = std::filesystem;

namespace curdle {
namespace {

struct ImageModule {
  ReadLuminanceFn read_luminance = nullptr;
  ReadSizeFn read_size = nullptr;
};

const ImageModule& module() {
  static ImageModule loaded;
  static std::once_flag once;
  static std::string failure;
  std::call_once(once, [] {
    void* handle = load_curdle_module(CURDLE_IMAGE_MODULE_NAME, &failure);
    if (!handle) return;
    loaded.read_luminance =
        reinterpret_cast<ReadLuminanceFn>(::dlsym(handle, "curdle_image_read_luminance_as"));
    loaded.read_size = reinterpret_cast<ReadSizeFn>(::dlsym(handle, "curdle_image_read_size_as"));
    if (!loaded.read_luminance || !loaded.read_size)
      failure = "the image module " CURDLE_IMAGE_MODULE_NAME " lacks its entry points";
  });
  if (!failure.empty()) throw std::runtime_error(failure);
  return loaded;
}

}  // namespace

LuminanceImage read_luminance(const fs::path& path, const char* format) {
  LuminanceImage image;
  std::string error;
  if (!module().read_luminance(path.c_str(), format, &image, &error))
    throw std::runtime_error(error);
  return image;
}

ImageSize read_image_size(const fs::path& path, const char* format) {
  ImageSize size;
  std::string error;
  if (!module().read_size(path.c_str(), format, &size, &error)) throw std::runtime_error(error);
  return size;
}

}  // namespace curdle
