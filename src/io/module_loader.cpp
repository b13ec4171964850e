#include "io/module_loader.h"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace fs = std::filesystem;

namespace curdle {
namespace {

// The directory of the file this code was loaded from: the program, or libcurdle.so when a
// program or the Python module links the library.
fs::path own_directory() {
  Dl_info info{};
  if (::dladdr(reinterpret_cast<const void*>(&own_directory), &info) == 0 || !info.dli_fname)
    return {};
  std::error_code ec;
  const fs::path file = fs::canonical(info.dli_fname, ec);
  return ec ? fs::path() : file.parent_path();
}

std::vector<fs::path> candidates(const std::string& name) {
  std::vector<fs::path> paths;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    paths.push_back(exe.parent_path() / name);
    paths.push_back(exe.parent_path() / ".." / CURDLE_MODULE_INSTALL_DIR / name);
  }
  if (const fs::path own = own_directory(); !own.empty()) {
    paths.push_back(own / name);
    paths.push_back(own / "curdle" / name);
  }
  paths.push_back(fs::path(CURDLE_MODULE_BUILD_DIR) / name);
  return paths;
}

}  // namespace

std::string find_curdle_module(const std::string& file_name, std::string* failure) {
  std::string tried;
  std::vector<fs::path> seen;
  for (const fs::path& path : candidates(file_name)) {
    const fs::path place = path.lexically_normal();
    if (std::find(seen.begin(), seen.end(), place) != seen.end()) continue;
    seen.push_back(place);
    std::error_code ec;
    if (fs::is_regular_file(path, ec)) return path.string();
    tried += (tried.empty() ? "" : ", ") + place.string();
  }
  *failure = "the module " + file_name + " is not installed (looked in " + tried + ")";
  return {};
}

void* load_curdle_module(const std::string& file_name, std::string* failure) {
  const std::string path = find_curdle_module(file_name, failure);
  if (path.empty()) return nullptr;
  void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) *failure = "cannot load " + path + ": " + ::dlerror();
  return handle;
}

}  // namespace curdle
