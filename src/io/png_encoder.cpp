// PNG encoding with zlib alone: layouts and previews are written without loading OpenImageIO,
// so that writing a picture costs the picture and not half a second of library loading.
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

#include "io/image.h"

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

// zlib's level 3: a third of level 6's time on a layout's drawing for files about a sixth
// larger (a perforated screen's 13 MB of pixels: 28 ms and 462 KB, against 79 ms and 394 KB).
constexpr int kLevel = 3;

// The sum of the bytes as signed values: the usual measure of how well a filtered row packs.
uint64_t signed_sum(const uint8_t* bytes, size_t size) {
  uint64_t sum = 0;
  for (size_t i = 0; i < size; ++i)
    sum += static_cast<uint8_t>(std::abs(static_cast<int8_t>(bytes[i])));
  return sum;
}

// The row filtered as PNG's none, sub and up (each after its filter type's byte), and what each
// costs. A loop of its own for each, with no test inside: they vectorise, where one loop doing
// all three was a twentieth of a building's whole run. `above` is all zeros for the first row.
std::array<uint64_t, 3> filtered(const std::vector<uint8_t>& row, const std::vector<uint8_t>& above,
                                 std::array<std::vector<uint8_t>, 3>& candidates) {
  const size_t stride = row.size();
  uint8_t* none = candidates[0].data() + 1;
  uint8_t* sub = candidates[1].data() + 1;
  uint8_t* up = candidates[2].data() + 1;
  std::memcpy(none, row.data(), stride);
  for (size_t i = 0; i < std::min<size_t>(3, stride); ++i) sub[i] = row[i];
  for (size_t i = 3; i < stride; ++i) sub[i] = static_cast<uint8_t>(row[i] - row[i - 3]);
  for (size_t i = 0; i < stride; ++i) up[i] = static_cast<uint8_t>(row[i] - above[i]);
  return {signed_sum(none, stride), signed_sum(sub, stride), signed_sum(up, stride)};
}

// The picture's rows, each with the filter (none, sub or up) whose bytes sum smallest as signed
// values (the usual heuristic: flat drawings compress to little), deflated as they are made:
// neither the filtered picture nor room for its worst case is ever held, for a sheet's 13 MB
// of pixels were two more buffers of 13 MB to fault in, a third of layout.png's time.
std::string deflated_rows(int width, int height, const PngRows& rows) {
  z_stream z{};
  if (deflateInit(&z, kLevel) != Z_OK)
    throw std::runtime_error("cannot encode a PNG: zlib will not start");
  // zlib's state is freed however the rows end (a row that throws included).
  const std::unique_ptr<z_stream, int (*)(z_stream*)> end_deflate(&z, deflateEnd);
  const size_t stride = static_cast<size_t>(width) * 3;
  std::vector<uint8_t> this_row(stride), row_above(stride);
  std::array<std::vector<uint8_t>, 3> candidates;
  for (auto& c : candidates) c.resize(stride + 1);
  std::string out;
  std::array<uint8_t, 1 << 16> buffer;
  // Deflates `row` (all of it), appending what zlib gives back; `flush` Z_FINISH at the end.
  auto deflate_row = [&](std::vector<uint8_t>* row, int flush) {
    z.next_in = row ? row->data() : nullptr;
    z.avail_in = row ? static_cast<uInt>(row->size()) : 0;
    int status = Z_OK;
    do {
      z.next_out = buffer.data();
      z.avail_out = static_cast<uInt>(buffer.size());
      status = deflate(&z, flush);
      out.append(reinterpret_cast<const char*>(buffer.data()), buffer.size() - z.avail_out);
    } while (z.avail_out == 0 || (flush == Z_FINISH && status == Z_OK));
    if (status == Z_STREAM_ERROR)
      throw std::runtime_error("cannot encode a PNG: zlib could not compress it");
  };
  for (int y = 0; y < height; ++y) {
    std::swap(this_row, row_above);
    rows(y, this_row.data());
    const std::array<uint64_t, 3> cost = filtered(this_row, row_above, candidates);
    size_t best = 0;
    for (size_t f = 1; f < 3; ++f)
      if (cost[f] < cost[best]) best = f;
    candidates[best][0] = static_cast<uint8_t>(best);  // PNG filter types 0, 1, 2
    deflate_row(&candidates[best], Z_NO_FLUSH);
  }
  deflate_row(nullptr, Z_FINISH);
  return out;
}

}  // namespace

std::string encode_png(const PreviewImage& image, double dpi) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<size_t>(image.width) * image.height * 3)
    throw std::runtime_error("cannot encode a PNG: the picture's size and pixels disagree");
  const size_t stride = static_cast<size_t>(image.width) * 3;
  return encode_png(
      image.width, image.height,
      [&](int y, uint8_t* rgb) {
        std::memcpy(rgb, image.rgb.data() + static_cast<size_t>(y) * stride, stride);
      },
      dpi);
}

std::string encode_png(int width, int height, const PngRows& rows, double dpi) {
  if (width <= 0 || height <= 0)
    throw std::runtime_error("cannot encode a PNG: a picture needs pixels");
  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string header;
  put32(header, static_cast<uint32_t>(width));
  put32(header, static_cast<uint32_t>(height));
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
  const std::string compressed = deflated_rows(width, height, rows);
  chunk(png, "IDAT", compressed);
  chunk(png, "IEND", "");
  return png;
}

}  // namespace curdle
