// PNG encoding with zlib alone: layouts and previews are written without loading OpenImageIO,
// so that writing a picture costs the picture and not half a second of library loading.
#include <zlib.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "export/image.h"

namespace curdle {
namespace {

void put32(std::string& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>(v >> shift & 0xff));
}

void chunk(std::string& out, const char type[5], const std::string& data) {
  put32(out, static_cast<uint32_t>(data.size()));
  const size_t start = out.size();
  out.append(type, 4);
  out += data;
  const auto* bytes = reinterpret_cast<const Bytef*>(out.data() + start);
  put32(out, static_cast<uint32_t>(crc32(0, bytes, static_cast<uInt>(out.size() - start))));
}

// Each row with the filter (none, sub or up) whose bytes sum smallest as signed values: the
// usual heuristic, and flat drawings compress to little.
std::string filtered_rows(const PreviewImage& image) {
  const size_t stride = static_cast<size_t>(image.width) * 3;
  std::string out;
  out.reserve((stride + 1) * static_cast<size_t>(image.height));
  std::array<std::string, 3> candidates;
  for (auto& c : candidates) c.resize(stride);
  for (int y = 0; y < image.height; ++y) {
    const uint8_t* row = image.rgb.data() + static_cast<size_t>(y) * stride;
    const uint8_t* above = y ? row - stride : nullptr;
    std::array<uint64_t, 3> cost{};
    for (size_t i = 0; i < stride; ++i) {
      const auto none = static_cast<uint8_t>(row[i]);
      const auto sub = static_cast<uint8_t>(row[i] - (i >= 3 ? row[i - 3] : 0));
      const auto up = static_cast<uint8_t>(row[i] - (above ? above[i] : 0));
      candidates[0][i] = static_cast<char>(none);
      candidates[1][i] = static_cast<char>(sub);
      candidates[2][i] = static_cast<char>(up);
      cost[0] += static_cast<uint64_t>(std::abs(static_cast<int8_t>(none)));
      cost[1] += static_cast<uint64_t>(std::abs(static_cast<int8_t>(sub)));
      cost[2] += static_cast<uint64_t>(std::abs(static_cast<int8_t>(up)));
    }
    size_t best = 0;
    for (size_t f = 1; f < 3; ++f)
      if (cost[f] < cost[best]) best = f;
    out.push_back(static_cast<char>(best));  // PNG filter types 0, 1, 2
    out += candidates[best];
  }
  return out;
}

// zlib's level 3: a third of level 6's time on a layout's drawing for files about a sixth
// larger (a perforated screen's 13 MB of pixels: 28 ms and 462 KB, against 79 ms and 394 KB).
constexpr int kLevel = 3;

}  // namespace

std::string encode_png(const PreviewImage& image, double dpi) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<size_t>(image.width) * image.height * 3)
    throw std::runtime_error("cannot encode a PNG: the picture's size and pixels disagree");
  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string header;
  put32(header, static_cast<uint32_t>(image.width));
  put32(header, static_cast<uint32_t>(image.height));
  header += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, no interlace
  chunk(png, "IHDR", header);
  if (dpi > 0) {  // pixels per metre, so that the picture prints at its size
    std::string physical;
    const auto per_metre = static_cast<uint32_t>(std::lround(dpi / 0.0254));
    put32(physical, per_metre);
    put32(physical, per_metre);
    physical.push_back(1);  // the unit is the metre
    chunk(png, "pHYs", physical);
  }
  const std::string raw = filtered_rows(image);
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string compressed(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(compressed.data()), &size,
                reinterpret_cast<const Bytef*>(raw.data()), static_cast<uLong>(raw.size()),
                kLevel) != Z_OK)
    throw std::runtime_error("cannot encode a PNG: zlib could not compress it");
  compressed.resize(size);
  chunk(png, "IDAT", compressed);
  chunk(png, "IEND", "");
  return png;
}

}  // namespace curdle
