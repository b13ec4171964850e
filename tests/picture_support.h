// Pictures the tests write: grey PNG files and their bytes, drawn by a function of the pixel.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "io/image.h"

namespace curdle::test {

// A PNG of width x height pixels, each `grey(x, y)` (0 black to 255 white), top row first.
inline std::string grey_png(int width, int height, const std::function<uint8_t(int, int)>& grey) {
  PreviewImage image;
  image.width = width, image.height = height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.rgb.insert(image.rgb.end(), 3, grey(x, y));
  return encode_png(image);
}

// A fresh folder of this test process's own.
inline std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("curdle-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::filesystem::path write_file(const std::filesystem::path& path,
                                        const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

}  // namespace curdle::test
