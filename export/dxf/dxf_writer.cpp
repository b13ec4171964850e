#include "export/dxf/dxf_writer.h"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <stdexcept>

#include "curdle/check.h"

namespace curdle {

// The base class opens a file of its own, written to by nothing here: /dev/null.
BufferedDxfWriter::BufferedDxfWriter(const std::filesystem::path& path)
    : DL_WriterA("/dev/null", DL_Codes::AC1015), buffer_(1 << 20) {
  out_.rdbuf()->pubsetbuf(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  out_.open(path, std::ios::binary | std::ios::trunc);
}

bool BufferedDxfWriter::finish() {
  out_.close();
  DL_WriterA::close();
  return !out_.fail();
}

void BufferedDxfWriter::group(int gc) const {
  const char* pad = gc < 10 ? "  " : gc < 100 ? " " : "";
  out_ << pad << gc << '\n';
}

void BufferedDxfWriter::dxfReal(int gc, double value) const {
  // Fixed with 16 decimals in the C locale (to_chars never writes a decimal comma, and is
  // exact without fmt's slow path for long precisions), then the zeros after the last
  // significant decimal cut, keeping at least one: 12.5000 -> 12.5, 3.0 -> 3.0.
  std::array<char, 400> buffer{};  // DBL_MAX has 309 digits before the point
  const auto written = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                     std::chars_format::fixed, 16);
  std::string text(buffer.data(), written.ptr);
  const size_t dot = text.find('.');
  if (dot != std::string::npos) {
    size_t end = dot + 2;
    for (size_t i = dot + 1; i < text.size(); ++i)
      if (text[i] != '0') end = std::max(end, i + 1);
    text.resize(std::min(end, text.size()));
  }
  dxfString(gc, text);
}

void BufferedDxfWriter::dxfInt(int gc, int value) const {
  group(gc);
  out_ << value << '\n';
}

void BufferedDxfWriter::dxfHex(int gc, int value) const {
  dxfString(gc, fmt::format("{:X}", static_cast<unsigned>(value)));
}

void BufferedDxfWriter::dxfString(int gc, const char* value) const {
  CHECK(value, "a DXF string that is null");
  group(gc);
  out_ << value << '\n';
}

void BufferedDxfWriter::dxfString(int gc, const std::string& value) const {
  group(gc);
  out_ << value << '\n';
}

}  // namespace curdle
