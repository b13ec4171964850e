#include "export/image.h"

#include <dlfcn.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <stdexcept>

#include "export/module_loader.h"
#include "export/png_reader.h"

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

// A PNG's bytes, read in process (png_reader.h); the callers have bounded the file's size.
std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw std::runtime_error("cannot read " + path.string());
  return bytes;
}

bool is_png(const char* format) { return std::strcmp(format, "png") == 0; }

}  // namespace

LuminanceImage read_luminance(const fs::path& path, const char* format) {
  if (is_png(format)) return read_png_luminance(file_bytes(path));
  LuminanceImage image;
  std::string error;
  if (!module().read_luminance(path.c_str(), format, &image, &error))
    throw std::runtime_error(error);
  return image;
}

ImageSize read_image_size(const fs::path& path, const char* format) {
  if (is_png(format)) return read_png_size(file_bytes(path));
  ImageSize size;
  std::string error;
  if (!module().read_size(path.c_str(), format, &size, &error)) throw std::runtime_error(error);
  return size;
}

}  // namespace curdle
