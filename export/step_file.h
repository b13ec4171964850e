// An ISO 10303-21 (STEP physical) file, written as it is built: the header first, then each
// entity the moment it is added, numbered #1, #2, ..., so that a model of a million elements
// never sits in memory as text. The IFC writer (ifc.h) is its one user.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace curdle {

// A STEP string literal: quotes and backslashes doubled, anything beyond ASCII encoded as
// \X2\hhhh\X0\ (UTF-16) so that the file is 7-bit whatever the names' script.
std::string step_string(std::string_view utf8);
// A STEP real: always with a decimal point ("600.", "0.5", "1.E-05"), shortest round trip.
std::string step_real(double value);
// The same, appended to `out` (a screen's IFC writes a million, most too long for a short
// string).
void append_step_real(std::string& out, double value);
// A reference list "(#1,#2,#3)".
std::string step_refs(const std::vector<int64_t>& ids);
// IFC's 22-character GlobalId (128 bits in IFC's base-64), derived from `key` alone, so that
// a model written twice has the same ids.
std::string ifc_guid(std::string_view key);

class StepWriter {
 public:
  // Writes the header: the file's name, its schema ("IFC4") and the view it follows.
  StepWriter(std::ostream& out, const std::string& file_name, const std::string& schema,
             const std::string& view);
  // Writes "#n=TEXT;" and returns n. `text` is an entity such as "IFCCARTESIANPOINT((0.,0.))".
  int64_t add(std::string_view text);
  // Ends the data section and the file, and writes out what is still held.
  void finish();
  int64_t count() const { return next_ - 1; }

 private:
  static constexpr size_t kFlushAt = 1 << 16;
  void flush();
  std::ostream& out_;
  std::string buffer_;  // entities not yet handed to the stream
  int64_t next_ = 1;
};

}  // namespace curdle
