#include "export/ifc/step_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "curdle/check.h"
#include "curdle/text.h"

namespace curdle {

bool plain_step_text(std::string_view text) {
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return c >= 0x20 && c < 0x7F && c != '\'' && c != '\\'; });
}

std::string step_string(std::string_view text) {
  std::string s;
  append_step_string(s, text);
  return s;
}

void append_step_string(std::string& s, std::string_view text) {
  s += '\'';
  if (plain_step_text(text)) {  // the usual case: written as it is
    s += text;
    s += '\'';
    return;
  }
  for (size_t i = 0; i < text.size();) {
    const uint32_t c = next_code_point(text, i);
    if (c == '\'' || c == '\\') {
      s += static_cast<char>(c);
      s += static_cast<char>(c);
    } else if (c >= 0x20 && c < 0x7F) {
      s += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7F) {
      s += fmt::format("\\X2\\{:04X}\\X0\\", c);  // names are refused with these; never raw
    } else if (c < 0x10000) {
      s += fmt::format("\\X2\\{:04X}\\X0\\", c);
    } else {
      s += fmt::format("\\X4\\{:08X}\\X0\\", c);
    }
  }
  s += '\'';
}

std::string step_real(double v) {
  std::string s;
  append_step_real(s, v);
  return s;
}

void append_step_real(std::string& out, double v) {
  std::array<char, 40> buffer;
  out.append(buffer.data(), write_step_real(buffer.data(), v));
}

char* write_step_real(char* first, double v) {
  CHECK(std::isfinite(v), "a STEP real must be finite");
  if (v == 0) {
    first[0] = '0';
    first[1] = '.';
    return first + 2;
  }
  // The shortest digits that read back as v, with the point STEP requires and E for the
  // exponent: 1 is "1.", 1e-07 is "1.E-07" (written in place: a screen's IFC has a million).
  char* end = std::to_chars(first, first + 32, v).ptr;
  char* e = std::find(first, end, 'e');
  if (std::find(first, e, '.') == e) {  // no point: open one before the exponent
    std::copy_backward(e, end, end + 1);
    *e++ = '.';
    ++end;
  }
  if (e != end) {
    *e = 'E';
    if (e[1] == '+') end = std::copy(e + 2, end, e + 1);
  }
  return end;
}

std::string step_refs(const std::vector<int64_t>& ids) {
  std::string s = "(";
  s.reserve(2 + ids.size() * 9);
  std::array<char, 24> digits;
  for (size_t i = 0; i < ids.size(); ++i) {
    s += i ? ",#" : "#";
    s.append(digits.data(), std::to_chars(digits.data(), digits.data() + 24, ids[i]).ptr);
  }
  s += ')';
  return s;
}

namespace {
// Two independent 64-bit hashes of the key (FNV-1a, then mixed as splitmix64 does).
uint64_t fnv(uint64_t h, std::string_view key) {
  for (const char c : key) h = (h ^ static_cast<uint8_t>(c)) * 0x100000001b3ULL;
  return h;
}
uint64_t mixed(uint64_t h) {
  h += 0x9e3779b97f4a7c15ULL;
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
  return h ^ (h >> 31);
}
}  // namespace

IfcGuidSource::IfcGuidSource(std::string_view prefix)
    : state_{fnv(0xcbf29ce484222325ULL, prefix), fnv(0x84222325cbf29ce4ULL, prefix)} {}

std::array<char, 22> IfcGuidSource::guid(std::string_view a, std::string_view b) const {
  static const char* kDigits = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_$";
  const uint64_t hi = mixed(fnv(fnv(state_[0], a), b));
  const uint64_t lo = mixed(fnv(fnv(state_[1], a), b));
  // 128 bits as 22 digits: the first holds 2 bits, the other 21 six each.
  std::array<char, 22> guid;
  for (int d = 21; d >= 0; --d) {
    const int bit = (21 - d) * 6;  // the digit's lowest bit, from the least significant end
    uint64_t six = bit < 64 ? lo >> bit : hi >> (bit - 64);
    if (bit < 64 && bit + 6 > 64) six |= hi << (64 - bit);
    guid[static_cast<size_t>(d)] = kDigits[six & (d == 0 ? 3 : 63)];
  }
  return guid;
}

std::string ifc_guid(std::string_view key) {
  const std::array<char, 22> guid = IfcGuidSource(key).guid({});
  return std::string(guid.begin(), guid.end());
}

StepWriter::StepWriter(std::ostream& out, const std::string& file_name, const std::string& schema,
                       const std::string& view)
    : out_(out) {
  // A fixed time stamp: the same recipe and seed give the same bytes.
  out_ << "ISO-10303-21;\nHEADER;\n"
       << "FILE_DESCRIPTION((" << step_string("ViewDefinition [" + view + "]") << "),'2;1');\n"
       << "FILE_NAME(" << step_string(file_name)
       << ",'2000-01-01T00:00:00',(''),(''),'curdle','curdle','');\n"
       << "FILE_SCHEMA((" << step_string(schema) << "));\nENDSEC;\nDATA;\n";
}

int64_t StepWriter::add(std::string_view text) {
  begin_entity();
  buffer_.append(text);
  return end_entity();
}

// Through a buffer of our own: five stream inserts per entity were a tenth of the file's time.
void StepWriter::begin_entity() {
  std::array<char, 24> id{};
  id[0] = '#';
  char* end = std::to_chars(id.data() + 1, id.data() + id.size() - 1, next_).ptr;
  *end++ = '=';
  buffer_.append(id.data(), end);
}

int64_t StepWriter::end_entity() {
  buffer_.append(std::string_view(";\n"));
  if (buffer_.size() >= kFlushAt) flush();
  return next_++;
}

void StepWriter::flush() {
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

void StepWriter::finish() {
  buffer_.append(std::string_view("ENDSEC;\nEND-ISO-10303-21;\n"));
  flush();
}

}  // namespace curdle
