#include "io/bounded_image.h"

#include <algorithm>
#include <fstream>
#include <optional>

#include "io/picture_gate.h"
#include "io/png_reader.h"

namespace curdle {
namespace {
constexpr uint64_t kMaxFileBytes = uint64_t{64} << 20;
}

LuminanceImage read_bounded_luminance(const std::filesystem::path& path, const std::string& what,
                                      const SourceLocation& where, uint64_t max_bytes,
                                      uint64_t max_pixels, const std::string& shown,
                                      int64_t max_side) {
  const std::string name = shown.empty() ? path.string() : shown;
  // The decoder's message may quote the path: shown by the same name.
  auto reason = [&](const std::runtime_error& e) {
    std::string text = e.what();
    const std::string p = path.string();
    for (size_t at = 0; !shown.empty() && (at = text.find(p, at)) != std::string::npos;
         at += shown.size())
      text.replace(at, p.size(), shown);
    return text;
  };
  // A device or a pipe (/dev/zero) would be read forever: regular files of bounded size only.
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(where, "cannot read " + what + " " + name + ": no such file");
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(where, what + " " + name + " is not a regular file");
  const uint64_t file_bytes = std::filesystem::file_size(path, ec);
  if (ec || file_bytes > kMaxFileBytes)
    throw InputError(where, what + " " + name + " is larger than 64 MiB");
  const std::string readable = std::string(" (") + kPictureFormats + ")";
  // The gate: only the formats curdle takes, sized by their own headers, reach a decoder.
  std::string bytes(file_bytes, '\0');
  std::ifstream in(path, std::ios::binary);
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
    throw InputError(where, "cannot read " + what + " " + name);
  std::string why;
  const std::optional<PictureHeader> header = read_picture_header(bytes, why);
  if (!header) throw InputError(where, "cannot read " + what + " " + name + ": " + why);
  if (static_cast<uint64_t>(header->width) > max_pixels / static_cast<uint64_t>(header->height) ||
      header->width > max_side || header->height > max_side)
    throw ResourceLimitError(where, what + " is " + std::to_string(header->width) + " x " +
                                        std::to_string(header->height) + " pixels; at most " +
                                        std::to_string(max_pixels) + " pixels and " +
                                        std::to_string(max_side) + " a side; use a smaller image");
  // A PNG is decoded in process from the bytes already read (png_reader.h); other formats by
  // the OpenImageIO module from the file.
  const bool png = header->format == PictureFormat::png;
  ImageSize size;
  try {
    size = png ? read_png_size(bytes) : read_image_size(path, decoder_name(header->format));
  } catch (const std::runtime_error& e) {
    throw InputError(where, "cannot read " + what + " " + name + ": " + reason(e) + readable);
  }
  // Decoded as floats per channel, then luminance and a grid of values: 4 bytes each.
  const uint64_t pixels = static_cast<uint64_t>(std::max(0, size.width)) *
                          static_cast<uint64_t>(std::max(0, size.height));
  const uint64_t need = pixels * (4 * static_cast<uint64_t>(std::max(1, size.channels)) + 8);
  if (pixels == 0 || pixels > max_pixels || need > max_bytes)
    throw ResourceLimitError(
        where, what + " is " + std::to_string(size.width) + " x " + std::to_string(size.height) +
                   " pixels, which would take about " + std::to_string(need >> 20) +
                   " MiB to read; at most " + std::to_string(max_pixels) + " pixels and " +
                   std::to_string(max_bytes >> 20) + " MiB; use a smaller image");
  try {
    return png ? read_png_luminance(bytes) : read_luminance(path, decoder_name(header->format));
  } catch (const std::runtime_error& e) {
    throw InputError(where, "cannot read " + what + " " + name + ": " + reason(e) + readable);
  }
}

}  // namespace curdle
