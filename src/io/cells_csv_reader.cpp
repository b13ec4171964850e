#include "io/cells_csv_reader.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <limits>
#include <set>

#include "curdle/error.h"

namespace curdle {
namespace {

constexpr int64_t kMaxCoordinate = int64_t{1} << 40;
constexpr const char* kAxes[] = {"x", "y", "z"};

// The text's lines without their CR LF (or LF), the byte-order mark skipped.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") text_.remove_prefix(3);
  }
  bool next(std::string_view& line) {
    if (text_.empty()) return false;
    const size_t end = text_.find('\n');
    line = text_.substr(0, end);
    text_.remove_prefix(end == std::string_view::npos ? text_.size() : end + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++number_;
    return true;
  }
  int64_t number() const { return number_; }

 private:
  std::string_view text_;
  int64_t number_ = 0;
};

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma == std::string_view::npos ? line.npos : comma - start));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

[[noreturn]] void refuse(int64_t line, const std::string& what) {
  throw InputError("cells.csv line " + std::to_string(line) + ": " + what);
}

int64_t whole(std::string_view field, int64_t line, const char* what) {
  int64_t v = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
  if (ec != std::errc() || end != field.data() + field.size() || v < -kMaxCoordinate ||
      v > kMaxCoordinate)
    refuse(line, std::string(what) + " must be a whole number from -2^40 to 2^40, not '" +
                     std::string(field.substr(0, 40)) + "'");
  return v;
}

// A curd's or a state's name as a recipe takes it.
bool plain_name(std::string_view name) {
  return !name.empty() && name.size() <= 200 && std::none_of(name.begin(), name.end(), [](char ch) {
    return ch == '"' || ch == '\\' || ch == '+' || static_cast<unsigned char>(ch) < 0x20;
  });
}

// State `state` (1 on) takes `name`, or already has it; false when it has another or `name`
// is another state's.
bool name_state(std::vector<std::string>& states, std::string_view name, uint32_t state) {
  if (state == 0 || state > states.size()) return false;
  std::string& held = states[state - 1];
  if (held == name) return true;
  if (!held.empty() || std::find(states.begin(), states.end(), name) != states.end()) return false;
  held = name;
  return true;
}

// The header's axes (into t.dimension) and curds (t.curds); returns the value's column.
size_t read_header(const std::vector<std::string_view>& header, CellsTable& t) {
  while (t.dimension < 3 && static_cast<size_t>(t.dimension) < header.size() &&
         header[static_cast<size_t>(t.dimension)] == kAxes[t.dimension])
    ++t.dimension;
  const size_t value_column = static_cast<size_t>(t.dimension);
  if (t.dimension == 0 || header.size() < value_column + 2 || header[value_column] != "value")
    refuse(1, "the header must be x[,y[,z]],value and one column per curd, as curdle writes it");
  for (size_t c = value_column + 1; c < header.size(); ++c) {
    const std::string_view name = header[c];
    // A recipe's curd names: these become the fitted recipe's.
    if (!plain_name(name))
      refuse(1, "curd column '" + std::string(name.substr(0, 40)) +
                    "' must be a name of 1 to 200 characters without quotes, backslashes, '+' or "
                    "control characters, as in a recipe");
    t.curds.emplace_back(header[c]);
  }
  if (t.curds.size() > 15) refuse(1, "at most 15 curds");
  return value_column;
}

}  // namespace

CellsTable parse_cells_csv(std::string_view text, uint64_t max_cells) {
  CellsTable t;
  Lines lines(text);
  std::string_view line;
  if (!lines.next(line))
    throw InputError("cells.csv is empty: it needs a header x,y,value,<curds>");
  const std::vector<std::string_view> header = split(line);
  const size_t value_column = read_header(header, t);
  const size_t columns = header.size();

  // First pass: the box; second: the cells. Rows are not kept, so memory is the box's bits.
  std::array<int64_t, 3> lo{0, 0, 0}, hi{0, 0, 0};
  uint64_t rows = 0;
  const auto body = [&](auto&& row) {
    Lines again(text);
    std::string_view l;
    again.next(l);
    while (again.next(l)) {
      if (l.empty()) continue;
      const std::vector<std::string_view> f = split(l);
      if (f.size() != columns)
        refuse(again.number(),
               std::to_string(f.size()) + " fields; the header has " + std::to_string(columns));
      std::array<int64_t, 3> at{0, 0, 0};
      for (int d = 0; d < t.dimension; ++d)
        at[d] = whole(f[static_cast<size_t>(d)], again.number(), kAxes[d]);
      row(at, f, again.number());
    }
  };
  // A column is a Markov curd's when its first cell names a state instead of a bit.
  const size_t curds = t.curds.size();
  std::vector<bool> named(curds, false);
  std::vector<std::set<std::string, std::less<>>> names(curds);
  body([&](const std::array<int64_t, 3>& at, const std::vector<std::string_view>& f, int64_t n) {
    for (int d = 0; d < t.dimension; ++d) {
      lo[d] = rows ? std::min(lo[d], at[d]) : at[d];
      hi[d] = rows ? std::max(hi[d], at[d]) : at[d];
    }
    for (size_t c = 0; c < curds; ++c) {
      const std::string_view field = f[value_column + 1 + c];
      if (!rows) named[c] = field != "0" && field != "1";
      if (!named[c] || names[c].contains(field)) continue;
      if (!plain_name(field))
        refuse(n, "curd '" + t.curds[c] + "' names a state '" + std::string(field.substr(0, 40)) +
                      "': a state's name is 1 to 200 characters without quotes, backslashes, "
                      "'+' or control characters");
      if (names[c].size() > 255) refuse(n, "curd '" + t.curds[c] + "' names over 255 states");
      names[c].emplace(field);
    }
    ++rows;
  });
  if (!rows) throw InputError("cells.csv has a header but no cells");
  uint64_t cells = 1;
  for (int d = 0; d < t.dimension; ++d) {
    t.box.origin[d] = lo[d];
    t.box.size[d] = hi[d] - lo[d] + 1;
    const auto side = static_cast<uint64_t>(t.box.size[d]);
    if (side > max_cells || cells > max_cells / side)
      throw ResourceLimitError("cells.csv covers a box of over " + std::to_string(max_cells) +
                               " cells; at most that many");
    cells *= side;
  }
  if (rows != cells)
    throw InputError("cells.csv has " + std::to_string(rows) + " rows for a box of " +
                     std::to_string(cells) + " cells: every cell of the box must be given once");
  // Each curd's bits in the value: a plain curd's one, a Markov curd's planes (enough for the
  // living states the file names).
  std::vector<int> first(curds, 0), planes(curds, 1);
  int bits = 0;
  t.states.assign(curds, {});
  for (size_t c = 0; c < curds; ++c) {
    if (named[c]) {
      const size_t living = names[c].size() - names[c].count("dead");
      planes[c] = std::max(1, static_cast<int>(std::bit_width(living)));
      t.states[c].assign((size_t{1} << planes[c]) - 1, "");
    }
    first[c] = bits;
    bits += planes[c];
  }
  if (bits > 16) refuse(1, "the curds take " + std::to_string(bits) + " bits of value; at most 16");
  t.cells.assign(curds, std::vector<bool>(cells, false));
  t.state_cells.assign(curds, std::vector<uint8_t>(cells, 0));
  std::vector<bool> seen(cells, false);
  body([&](const std::array<int64_t, 3>& at, const std::vector<std::string_view>& f, int64_t n) {
    const size_t i = static_cast<size_t>(
        ((at[2] - lo[2]) * t.box.size[1] + (at[1] - lo[1])) * t.box.size[0] + (at[0] - lo[0]));
    if (seen[i]) refuse(n, "the cell is given twice");
    seen[i] = true;
    const int64_t stated = whole(f[value_column], n, "value");
    int64_t value = 0;
    for (size_t c = 0; c < curds; ++c) {
      const std::string_view field = f[value_column + 1 + c];
      uint32_t state = 0;
      if (!named[c]) {
        if (field != "0" && field != "1")
          refuse(n, "curd '" + t.curds[c] + "' must be 0 or 1, as in the first row, not '" +
                        std::string(field.substr(0, 40)) + "'");
        state = field == "1";
      } else {
        state = static_cast<uint32_t>(stated >> first[c]) & ((1u << planes[c]) - 1);
        if (field == "dead" ? state != 0 : !name_state(t.states[c], field, state))
          refuse(n, "curd '" + t.curds[c] + "' is '" + std::string(field.substr(0, 40)) +
                        "' where value " + std::to_string(stated) + " gives its state " +
                        std::to_string(state) + (state ? ", another state's" : ", dead") +
                        ": a state's name must go with one number in every row");
      }
      value |= int64_t{state} << first[c];
      t.state_cells[c][i] = static_cast<uint8_t>(state);
      t.cells[c][i] = state != 0;
    }
    if (stated != value)
      refuse(n, "value " + std::string(f[value_column]) + " is not the sum of its curds' bits (" +
                    std::to_string(value) + ")");
  });
  for (auto& s : t.states)  // the numbers no cell has, past the last named one
    while (!s.empty() && s.back().empty()) s.pop_back();
  for (size_t c = 0; c < curds; ++c)
    if (named[c] && t.states[c].empty()) t.states[c] = {""};  // every cell dead: one state
  return t;
}

}  // namespace curdle
