#include "export/dxf/dxf_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <stdexcept>

#include "curdle/check.h"
#include "curdle/fixed_text.h"

namespace curdle {

// The base class opens a file of its own, written to by nothing here: /dev/null.
BufferedDxfWriter::BufferedDxfWriter(const std::filesystem::path& path)
    : DL_WriterA("/dev/null", DL_Codes::AC1015) {
  buffer_.reserve(kFlushAt + 4096);
  out_.open(path, std::ios::binary | std::ios::trunc);
}

BufferedDxfWriter::~BufferedDxfWriter() {
  if (out_.is_open()) flush();
}

bool BufferedDxfWriter::finish() {
  flush();
  out_.close();
  DL_WriterA::close();
  return !out_.fail();
}

void BufferedDxfWriter::flush() const {
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

void BufferedDxfWriter::line(std::string_view text) const {
  buffer_.append(text);
  buffer_ += '\n';
  if (buffer_.size() >= kFlushAt) flush();
}

void BufferedDxfWriter::group(int gc) const {
  std::array<char, 16> text{' ', ' '};
  char* first = text.data() + (gc < 10 ? 2 : gc < 100 ? 1 : 0);
  char* end = std::to_chars(first, text.data() + text.size(), gc).ptr;
  line(std::string_view(text.data(), end));
}

void BufferedDxfWriter::dxfReal(int gc, double value) const {
  // Fixed with 16 decimals in the C locale (to_chars never writes a decimal comma, and is exact
  // without fmt's slow path for long precisions; to_chars_fixed is its fast path for what a
  // drawing holds), then the zeros after the last significant decimal cut, keeping at least
  // one: 12.5000 -> 12.5, 3.0 -> 3.0.
  std::array<char, 400> buffer{};  // DBL_MAX has 309 digits before the point
  const char* first = buffer.data();
  const char* end = to_chars_fixed(buffer.data(), buffer.data() + buffer.size(), value, 16).ptr;
  const char* dot = std::find(first, end, '.');
  if (dot != end) {
    const char* last = dot + 2;  // one decimal at least
    for (const char* c = dot + 1; c < end; ++c)
      if (*c != '0') last = std::max(last, c + 1);
    end = std::min(last, end);
  }
  group(gc);
  line(std::string_view(first, end));
}

void BufferedDxfWriter::dxfInt(int gc, int value) const {
  group(gc);
  std::array<char, 16> text{};
  line(std::string_view(text.data(), std::to_chars(text.data(), text.data() + 16, value).ptr));
}

void BufferedDxfWriter::dxfHex(int gc, int value) const {
  dxfString(gc, fmt::format("{:X}", static_cast<unsigned>(value)));
}

void BufferedDxfWriter::dxfString(int gc, const char* value) const {
  CHECK(value, "a DXF string that is null");
  group(gc);
  line(value);
}

void BufferedDxfWriter::dxfString(int gc, const std::string& value) const {
  group(gc);
  line(value);
}

}  // namespace curdle
