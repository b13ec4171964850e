// An ASCII DXF as its groups: a group code line and a value line, with the line number for
// messages. Read strictly, since a lax reading is silently wrong: a code is an integer, a
// number is one number in the C locale ("1,5" and "1 2" are refused, not read as 1), and no
// line is longer than a DXF's longest, so that damaged or hostile bytes are refused by line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace curdle::site {

struct DxfGroup {
  int code = -1;
  std::string_view value;  // without the line's end and the spaces around it
  size_t line = 0;         // of the value, counted from 1
};

// The longest line a DXF holds: AutoCAD writes text of at most 2,049 characters a line; a
// margin above it for other writers.
inline constexpr size_t kLongestDxfLine = 65536;

class DxfGroups {
 public:
  DxfGroups(std::string_view bytes, std::string file);

  // The next group into `group`; false at the end of the bytes. Throws InputError for a code
  // that is not an integer or a line longer than kLongestDxfLine.
  bool next(DxfGroup& group);
  // The group read again by the next call to next().
  void put_back(const DxfGroup& group);

  // A real number (codes 10-59, 110-149, 210-239, 460-469, 1010-1059), or InputError naming the
  // line, the group and `entity` ("LWPOLYLINE 2A").
  double real(const DxfGroup& group, std::string_view entity) const;
  // An integer (codes 60-99, 170-179, 270-289, 370-389, 400-409, 1060-1071).
  int64_t integer(const DxfGroup& group, std::string_view entity) const;

  // The first group of `code` among an entity's `groups`, read as real or integer does; the
  // fallback where the entity has none.
  double real_of(const std::vector<DxfGroup>& groups, int code, double fallback,
                 std::string_view entity) const;
  int64_t integer_of(const std::vector<DxfGroup>& groups, int code, int64_t fallback,
                     std::string_view entity) const;

  const std::string& file() const { return file_; }

 private:
  std::string_view line();

  std::string_view bytes_;
  std::string file_;
  size_t at_ = 0, line_ = 0;
  bool held_ = false;
  DxfGroup held_group_;
};

// A name as the drawing wrote it (a layer's, a block's): UTF-8, or Windows-1252 in older files,
// with `\U+XXXX` the DXF escape for any other character; control characters shown escaped
// (shown_name).
std::string decoded_name(std::string_view raw);

}  // namespace curdle::site
