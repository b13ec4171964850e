// An ISO 10303-21 (STEP physical) file, written as it is built: the header first, then each
// entity the moment it is added, numbered #1, #2, ..., so that a model of a million elements
// never sits in memory as text. The IFC writer (ifc.h) is its one user.
#pragma once

#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <iterator>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curdle {

// A STEP string literal: quotes and backslashes doubled, anything beyond ASCII encoded as
// \X2\hhhh\X0\ (UTF-16) so that the file is 7-bit whatever the names' script.
std::string step_string(std::string_view utf8);
// The same, appended to `out`.
void append_step_string(std::string& out, std::string_view utf8);
// Whether `utf8` is written as it is between the quotes (printable ASCII, no quote or backslash).
bool plain_step_text(std::string_view utf8);
// A STEP real: always with a decimal point ("600.", "0.5", "1.E-05"), shortest round trip.
std::string step_real(double value);
// The same, appended to `out` (a screen's IFC writes a million, most too long for a short
// string).
void append_step_real(std::string& out, double value);
// The same, written at `first` (room for 40 characters); returns its end.
char* write_step_real(char* first, double value);
// A reference list "(#1,#2,#3)".
std::string step_refs(const std::vector<int64_t>& ids);
// IFC's 22-character GlobalId (128 bits in IFC's base-64), derived from `key` alone, so that
// a model written twice has the same ids.
std::string ifc_guid(std::string_view key);

// The GlobalIds of keys that all begin with `prefix` (a model's recipe, seed and view), the
// prefix hashed once: guid(a, b) is ifc_guid(prefix + a + b), without the string.
class IfcGuidSource {
 public:
  explicit IfcGuidSource(std::string_view prefix = {});
  std::array<char, 22> guid(std::string_view a, std::string_view b = {}) const;

 private:
  std::array<uint64_t, 2> state_;  // the two hashes after the prefix
};

// What fmt writes straight into an entity's text, so that an entity of a dozen attributes
// makes no string of its own for each (a brick façade's model has 200,000 entities).
struct StepRef {  // "#12"
  int64_t id;
};
struct StepReal {  // as step_real
  double value;
};
struct StepText {  // as step_string
  std::string_view utf8;
};
struct StepRoot {  // a rooted entity's first attributes: "'GlobalId',#owner-history"
  std::array<char, 22> guid;
  int64_t owner_history;
};
// Short names for them where entities are written: add(FMT_COMPILE("IFCX({},{})"), ref(id),
// real(x)).
namespace step {
inline StepRef ref(int64_t id) { return {id}; }
inline StepReal real(double value) { return {value}; }
inline StepText text(std::string_view utf8) { return {utf8}; }
}  // namespace step

class StepWriter {
 public:
  // Writes the header: the file's name, its schema ("IFC4") and the view it follows.
  StepWriter(std::ostream& out, const std::string& file_name, const std::string& schema,
             const std::string& view);
  // Writes "#n=TEXT;" and returns n. `text` is an entity such as "IFCCARTESIANPOINT((0.,0.))".
  int64_t add(std::string_view text);
  // The same with the entity formatted in place from a compiled format, so that no format is
  // parsed again for each entity (a third of the pavilion's model was fmt reading its formats):
  // add(FMT_COMPILE("IFCDIRECTION(({},{},{}))"), x, y, z).
  template <typename Format, typename First, typename... Rest>
  int64_t add(const Format& format, First&& first, Rest&&... rest) {
    begin_entity();
    fmt::format_to(fmt::appender(buffer_), format, std::forward<First>(first),
                   std::forward<Rest>(rest)...);
    return end_entity();
  }
  // Ends the data section and the file, and writes out what is still held.
  void finish();
  int64_t count() const { return next_ - 1; }

 private:
  static constexpr size_t kFlushAt = 1 << 16;
  void begin_entity();   // "#n="
  int64_t end_entity();  // ";\n", and n
  void flush();
  std::ostream& out_;
  fmt::memory_buffer buffer_;  // entities not yet handed to the stream
  int64_t next_ = 1;
};

}  // namespace curdle

template <>
struct fmt::formatter<curdle::StepRef> : fmt::formatter<std::string_view> {
  template <typename Context>
  auto format(const curdle::StepRef& r, Context& context) const {
    std::array<char, 24> text{'#'};
    char* end = std::to_chars(text.data() + 1, text.data() + text.size(), r.id).ptr;
    return std::copy(text.data(), end, context.out());
  }
};
template <>
struct fmt::formatter<curdle::StepReal> : fmt::formatter<std::string_view> {
  template <typename Context>
  auto format(const curdle::StepReal& r, Context& context) const {
    std::array<char, 40> text;
    return std::copy(text.data(), curdle::write_step_real(text.data(), r.value), context.out());
  }
};
template <>
struct fmt::formatter<curdle::StepText> : fmt::formatter<std::string_view> {
  template <typename Context>
  auto format(const curdle::StepText& t, Context& context) const {
    if (curdle::plain_step_text(t.utf8)) {  // the usual case: written as it is, quoted
      auto out = context.out();
      *out++ = '\'';
      out = std::copy(t.utf8.begin(), t.utf8.end(), out);
      *out++ = '\'';
      return out;
    }
    std::string text;
    curdle::append_step_string(text, t.utf8);
    return std::copy(text.begin(), text.end(), context.out());
  }
};
template <>
struct fmt::formatter<curdle::StepRoot> : fmt::formatter<std::string_view> {
  template <typename Context>
  auto format(const curdle::StepRoot& r, Context& context) const {
    auto out = context.out();
    *out++ = '\'';
    out = std::copy(r.guid.begin(), r.guid.end(), out);
    *out++ = '\'';
    *out++ = ',';
    return fmt::formatter<curdle::StepRef>().format(curdle::StepRef{r.owner_history}, context);
  }
};
