#include "export/image.h"

#include <dlfcn.h>
#include <unistd.h>

#include <mutex>
#include <stdexcept>

namespace fs = std::filesystem;

namespace curdle {
namespace {

struct ImageModule {
  ReadLuminanceFn read_luminance = nullptr;
  ReadSizeFn read_size = nullptr;
};

// The directory of the file this code was loaded from: the program, or libcurdle.so when a
// program or the Python module links the installed library.
fs::path own_directory() {
  Dl_info info{};
  if (::dladdr(reinterpret_cast<const void*>(&own_directory), &info) == 0 || !info.dli_fname)
    return {};
  std::error_code ec;
  const fs::path file = fs::canonical(info.dli_fname, ec);
  return ec ? fs::path() : file.parent_path();
}

// Beside the program (build tree), in ../lib/curdle (installed), in curdle/ beside the shared
// library (installed, linked by another program), or where it was built.
std::vector<fs::path> candidates() {
  std::vector<fs::path> paths;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    paths.push_back(exe.parent_path() / CURDLE_IMAGE_MODULE_NAME);
    paths.push_back(exe.parent_path() / ".." / CURDLE_IMAGE_MODULE_INSTALL_DIR /
                    CURDLE_IMAGE_MODULE_NAME);
  }
  if (const fs::path own = own_directory(); !own.empty())
    paths.push_back(own / "curdle" / CURDLE_IMAGE_MODULE_NAME);
  paths.push_back(fs::path(CURDLE_IMAGE_MODULE_BUILD_DIR) / CURDLE_IMAGE_MODULE_NAME);
  return paths;
}

const ImageModule& module() {
  static ImageModule loaded;
  static std::once_flag once;
  static std::string failure;
  std::call_once(once, [] {
    std::string tried;
    for (const fs::path& path : candidates()) {
      std::error_code ec;
      if (!fs::is_regular_file(path, ec)) {
        tried += (tried.empty() ? "" : ", ") + path.lexically_normal().string();
        continue;
      }
      void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        failure = std::string("cannot load the image module: ") + ::dlerror();
        return;
      }
      loaded.read_luminance =
          reinterpret_cast<ReadLuminanceFn>(::dlsym(handle, "curdle_image_read_luminance_as"));
      loaded.read_size = reinterpret_cast<ReadSizeFn>(::dlsym(handle, "curdle_image_read_size_as"));
      if (!loaded.read_luminance || !loaded.read_size)
        failure = "the image module " + path.string() + " lacks its entry points";
      return;
    }
    failure =
        "the image module " CURDLE_IMAGE_MODULE_NAME " is not installed (looked in " + tried + ")";
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
