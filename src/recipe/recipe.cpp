#include "recipe/recipe.h"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>
#include <sstream>

#include "curdle/error.h"
#include "layout/builder.h"
#include "layout/park.h"

namespace curdle {
namespace {

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

// Where the recipe came from: its file, and the keys the command line overrode.
struct Source {
  std::string file;
  std::vector<std::string> overridden;  // dotted keys given with --set
};

SourceLocation locate(const Source& source, const toml::source_region& region,
                      const std::string& key) {
  for (const auto& o : source.overridden)
    if (key == o || key.rfind(o + ".", 0) == 0 || o.rfind(key + ".", 0) == 0)
      return SourceLocation{"--set " + o, 0, 0, key};
  SourceLocation where{source.file, 0, 0, key};
  where.line = static_cast<int>(region.begin.line);
  where.column = static_cast<int>(region.begin.column);
  return where;
}

// Reads one table whose allowed keys are known up front, so that an unknown key (often a
// misspelt required one) is reported before anything else.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string path, const Source& source,
              std::vector<std::string> allowed)
      : table_(table), path_(std::move(path)), source_(source), known_(std::move(allowed)) {
    reject_unknown();
  }

  const toml::node* get(const std::string& key) const { return table_.get(key); }
  std::string key_path(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
  }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    const toml::node* n = table_.get(key);
    throw InputError(locate(source_, n ? n->source() : table_.source(), key_path(key)), what);
  }
  [[noreturn]] void fail_node(const toml::node& n, const std::string& key_path,
                              const std::string& what) const {
    throw InputError(locate(source_, n.source(), key_path), what);
  }

  // Every key not asked for is an error, with the closest known key as a suggestion.
  void reject_unknown() const {
    if (table_.empty()) return;
    for (auto&& [k, v] : table_) {
      const std::string key(k.str());
      if (std::find(known_.begin(), known_.end(), key) != known_.end()) continue;
      std::string best;
      size_t best_d = 99;
      for (const auto& candidate : known_) {
        const size_t d = edit_distance(key, candidate);
        if (d < best_d) best_d = d, best = candidate;
      }
      std::string msg = "unknown key '" + key + "'";
      if (best_d <= std::max<size_t>(2, key.size() / 3))
        msg += "; did you mean '" + best + "'?";
      else
        msg += ".";
      msg += " Allowed here: " + join(known_) + ".";
      throw InputError(locate(source_, v.source(), key_path(key)), msg);
    }
  }

  const Source& source() const { return source_; }

 private:
  const toml::table& table_;
  std::string path_;
  const Source& source_;
  std::vector<std::string> known_;
};

int64_t read_int(TableReader& r, const std::string& key, int64_t fallback, int64_t lo, int64_t hi,
                 bool required = false) {
  const toml::node* n = r.get(key);
  if (!n) {
    if (required)
      r.fail(key, "is required: a whole number from " + std::to_string(lo) + " to " +
                      std::to_string(hi));
    return fallback;
  }
  const auto v = n->value<int64_t>();
  if (!n->is_integer() || !v || *v < lo || *v > hi)
    r.fail(key, "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
  return *v;
}

std::optional<std::string> read_string(TableReader& r, const std::string& key,
                                       const std::string& allowed = "text") {
  const toml::node* n = r.get(key);
  if (!n) return std::nullopt;
  if (!n->is_string()) r.fail(key, "must be a string in double quotes: " + allowed);
  return *n->value<std::string>();
}

const toml::table* read_table(TableReader& r, const std::string& key) {
  const toml::node* n = r.get(key);
  if (!n) return nullptr;
  if (!n->is_table()) r.fail(key, "must be a table, written [" + key + "]");
  return n->as_table();
}

std::optional<Rgb> parse_colour(std::string_view s) {
  if (s.size() != 7 || s[0] != '#') return std::nullopt;
  unsigned v = 0;
  auto [p, ec] = std::from_chars(s.data() + 1, s.data() + 7, v, 16);
  if (ec != std::errc() || p != s.data() + 7) return std::nullopt;
  return Rgb{static_cast<uint8_t>(v >> 16), static_cast<uint8_t>(v >> 8), static_cast<uint8_t>(v)};
}

Probability read_probability(const TableReader& r, const toml::node& n, const std::string& path) {
  std::optional<Probability> p;
  if (n.is_string())
    p = Probability::parse(*n.value<std::string>());
  else if (n.is_integer())
    p = Probability::from_double(static_cast<double>(*n.value<int64_t>()));
  else if (n.is_floating_point())
    p = Probability::from_double(*n.value<double>());
  if (!p)
    r.fail_node(n, path,
                "a probability is a fraction like \"3/4\" or a decimal like \"0.75\", from 0 to 1");
  return *p;
}

Lattice read_lattice(TableReader& top) {
  const toml::table* t = read_table(top, "lattice");
  if (!t) top.fail("lattice", "is required: [lattice] with base, dimension and mode");
  TableReader r(*t, "lattice", top.source(), {"base", "dimension", "stages", "mode"});
  Lattice l;
  l.base = static_cast<int>(read_int(r, "base", 0, 2, kMaxBase, true));
  l.dimension = static_cast<int>(read_int(r, "dimension", 0, 1, 3, true));
  l.stages = static_cast<int>(read_int(r, "stages", 0, 1, 63));
  const auto mode =
      read_string(r, "mode", "\"canonical\", \"exact\" or \"quota\"").value_or("canonical");
  if (mode == "canonical")
    l.mode = Mode::canonical;
  else if (mode == "exact")
    l.mode = Mode::exact;
  else if (mode == "quota")
    l.mode = Mode::quota;
  else
    r.fail("mode", "must be \"canonical\", \"exact\" or \"quota\", not \"" + mode + "\"");
  return l;
}

std::vector<CurdSpec> read_curds(TableReader& top, Lattice& lattice) {
  const toml::node* n = top.get("curds");
  if (!n) top.fail("curds", "is required: at least one [[curds]] with name and probabilities");
  const toml::array* arr = n->as_array();
  if (!arr || !arr->is_array_of_tables())
    top.fail("curds", "must be an array of tables, written [[curds]]");
  if (arr->empty() || arr->size() > kMaxCurds)
    top.fail("curds", "must have from 1 to " + std::to_string(kMaxCurds) + " curds, not " +
                          std::to_string(arr->size()));
  std::vector<CurdSpec> curds;
  std::set<std::string> names;
  const int stated_stages = lattice.stages;  // 0 when [lattice] does not say
  int stages = 0;
  for (size_t i = 0; i < arr->size(); ++i) {
    const std::string path = "curds." + std::to_string(i);
    TableReader r(*arr->get(i)->as_table(), path, top.source(),
                  {"name", "probabilities", "colour"});
    CurdSpec curd;
    curd.name = read_string(r, "name").value_or("curd" + std::to_string(i));
    if (curd.name.empty() || curd.name.find_first_of(",\"\n\r+") != std::string::npos)
      r.fail("name", "must be a non-empty name without commas, quotes, '+' or line breaks");
    if (!names.insert(curd.name).second)
      r.fail("name", "'" + curd.name + "' is used by another curd; names must differ");
    const toml::node* pn = r.get("probabilities");
    if (!pn)
      r.fail("probabilities", "is required: one probability per stage, e.g. [\"3/4\", \"2/3\"]");
    const toml::array* ps = pn->as_array();
    if (!ps || ps->empty())
      r.fail("probabilities", "must be a non-empty array, one per stage, e.g. [\"3/4\", \"2/3\"]");
    for (size_t k = 0; k < ps->size(); ++k)
      curd.probabilities.push_back(
          read_probability(r, *ps->get(k), path + ".probabilities." + std::to_string(k)));
    const int K = static_cast<int>(curd.probabilities.size());
    if (K > 63) r.fail("probabilities", "at most 63 stages");
    if (stages == 0) stages = K;
    if (K != stages)
      r.fail("probabilities", "has " + std::to_string(K) + " stages but curd 0 has " +
                                  std::to_string(stages) +
                                  "; all curds share the lattice's stages");
    if (auto c = read_string(r, "colour", "a colour written \"#rrggbb\"")) {
      curd.colour = parse_colour(*c);
      if (!curd.colour) r.fail("colour", "must be a colour written \"#rrggbb\", e.g. \"#c0392b\"");
    }
    curds.push_back(std::move(curd));
  }
  if (stated_stages != 0 && stated_stages != stages)
    top.fail("curds", "the curds have " + std::to_string(stages) +
                          " probabilities each but lattice.stages is " +
                          std::to_string(stated_stages));
  lattice.stages = stages;
  return curds;
}

void check_size(TableReader& top, const Lattice& l) {
  const double path_bits = l.dimension * l.stages * std::log2(static_cast<double>(l.base));
  if (path_bits > kMaxPathBits + 1e-9)
    top.fail("curds", "b^(E K) = " + std::to_string(l.base) + "^(" + std::to_string(l.dimension) +
                          "*" + std::to_string(l.stages) +
                          ") cells per root is too many; at most 2^" +
                          std::to_string(kMaxPathBits) + " (fewer stages or a smaller base)");
}

void check_exact(TableReader& top, const Lattice& l, const std::vector<CurdSpec>& curds) {
  if (l.mode != Mode::exact) return;
  const uint64_t B = l.children();
  for (size_t i = 0; i < curds.size(); ++i)
    for (size_t k = 0; k < curds[i].probabilities.size(); ++k) {
      const Probability& p = curds[i].probabilities[k];
      if (p.times_is_whole(B)) continue;
      const std::string path = "curds." + std::to_string(i) + ".probabilities." + std::to_string(k);
      const auto* table = top.get("curds")->as_array()->get(i)->as_table();
      const toml::node* node = table->get("probabilities")->as_array()->get(k);
      top.fail_node(*node, path,
                    "exact mode keeps p * b^E of the " + std::to_string(B) +
                        " subcells of each survivor, and " + p.text() + " * " + std::to_string(B) +
                        " = " + std::to_string(p.value() * B) +
                        " is not a whole number; use a multiple of 1/" + std::to_string(B) +
                        ", or mode \"canonical\" or \"quota\"");
    }
}

Box read_field(TableReader& top, const Lattice& l, std::optional<Box>& window) {
  Box field;
  const int64_t side = static_cast<int64_t>(l.root_side());
  for (int d = 0; d < l.dimension; ++d) field.size[d] = side;
  const toml::table* t = read_table(top, "field");
  if (!t) return field;
  TableReader r(*t, "field", top.source(), {"cells", "window"});
  const int64_t max_roots = l.dimension == 1 ? (int64_t{1} << 32) : l.dimension == 2 ? 65536 : 1024;
  auto read_numbers = [&](const std::string& key,
                          size_t count) -> std::optional<std::vector<int64_t>> {
    const toml::node* n = r.get(key);
    if (!n) return std::nullopt;
    const toml::array* a = n->as_array();
    std::vector<int64_t> v;
    if (a && a->size() == count)
      for (auto&& e : *a)
        if (auto x = e.value<int64_t>(); x && e.is_integer()) v.push_back(*x);
    if (v.size() != count)
      r.fail(key, "must be " + std::to_string(count) + " whole numbers for a " +
                      std::to_string(l.dimension) + "-D lattice");
    return v;
  };
  if (auto cells = read_numbers("cells", l.dimension)) {
    for (int d = 0; d < l.dimension; ++d) {
      if ((*cells)[d] < 1 || (*cells)[d] > max_roots * side)
        r.fail("cells", "each size must be from 1 to " + std::to_string(max_roots * side) +
                            " cells (" + std::to_string(max_roots) + " root cells of " +
                            std::to_string(side) + ")");
      field.size[d] = (*cells)[d];
    }
  }
  if (auto w = read_numbers("window", 2 * l.dimension)) {
    Box box;
    for (int d = 0; d < l.dimension; ++d) {
      box.origin[d] = (*w)[d];
      box.size[d] = (*w)[l.dimension + d];
    }
    if (box.cells() == 0 || box.origin[0] < 0 || box.origin[1] < 0 || box.origin[2] < 0)
      r.fail("window", "must have origin >= 0 and sizes >= 1");
    window = box;  // checked against the field once the layout has sized it
  }
  return field;
}

double read_mm(TableReader& r, const std::string& key, double fallback, double lo,
               bool required = false) {
  const toml::node* n = r.get(key);
  if (!n) {
    if (required) r.fail(key, "is required: a length in millimetres");
    return fallback;
  }
  const auto v = n->value<double>();
  if (!v || !std::isfinite(*v) || *v < lo || *v > 1e7)
    r.fail(key, "must be a length in millimetres from " + std::to_string(static_cast<int>(lo)) +
                    " to 10 km");
  return *v;
}

std::optional<std::array<double, 2>> read_mm_pair(TableReader& r, const std::string& key,
                                                  bool required = false) {
  const toml::node* n = r.get(key);
  if (!n) {
    if (required) r.fail(key, "is required: [width, height] in millimetres");
    return std::nullopt;
  }
  const toml::array* a = n->as_array();
  std::array<double, 2> v{};
  if (!a || a->size() != 2) r.fail(key, "must be [width, height] in millimetres");
  for (size_t i = 0; i < 2; ++i) {
    const auto x = a->get(i)->value<double>();
    if (!x || !std::isfinite(*x) || *x <= 0 || *x > 1e7)
      r.fail(key, "must be [width, height] in millimetres, each above 0 and up to 10 km");
    v[i] = *x;
  }
  return v;
}

bool read_bool(TableReader& r, const std::string& key, bool fallback) {
  const toml::node* n = r.get(key);
  if (!n) return fallback;
  if (!n->is_boolean()) r.fail(key, "must be true or false");
  return *n->value<bool>();
}

void read_perforation(TableReader& r, const Design& design, LayoutSpec& spec) {
  spec.thickness = read_mm(r, "thickness", 0, 0, true);
  if (spec.thickness <= 0) r.fail("thickness", "must be above 0 mm");
  spec.min_diameter = read_mm(r, "min_diameter", 0, 0);
  spec.min_bridge = read_mm(r, "min_bridge", 0, 0);
  spec.edge_margin = read_mm(r, "edge_margin", 0, 0);
  spec.chord_tolerance = read_mm(r, "chord_tolerance", 0.05, 0);
  if (spec.chord_tolerance <= 0) r.fail("chord_tolerance", "must be above 0 mm, e.g. 0.05");
  const auto fix = read_string(r, "fix", "\"none\" or \"drop\"").value_or("none");
  if (fix == "none")
    spec.fix = HoleFix::none;
  else if (fix == "drop")
    spec.fix = HoleFix::drop;
  else
    r.fail("fix",
           "must be \"none\" (report only) or \"drop\" (drop the openings that break a rule)");
  const toml::node* n = r.get("holes");
  if (!n)
    r.fail(
        "holes",
        "is required: one {diameter, offset} per curd, e.g. [{diameter = 20, offset = [-10, 0]}]");
  const toml::array* a = n->as_array();
  if (!a || a->size() != design.curds.size())
    r.fail("holes",
           "must give one {diameter, offset} per curd: " + std::to_string(design.curds.size()) +
               " curds, " + std::to_string(a ? a->size() : 0) + " holes");
  for (size_t i = 0; i < a->size(); ++i) {
    const std::string path = "layout.holes." + std::to_string(i);
    const toml::table* h = a->get(i)->as_table();
    if (!h) r.fail_node(*a->get(i), path, "must be a table {diameter = 20, offset = [0, 0]}");
    TableReader hr(*h, path, r.source(), {"diameter", "offset"});
    HoleSpec hole;
    hole.diameter = read_mm(hr, "diameter", 0, 0, true);
    if (hole.diameter <= 0) hr.fail("diameter", "must be above 0 mm");
    if (const auto off = hr.get("offset")) {
      const toml::array* o = off->as_array();
      const auto x = o && o->size() == 2 ? o->get(0)->value<double>() : std::nullopt;
      const auto y = o && o->size() == 2 ? o->get(1)->value<double>() : std::nullopt;
      if (!x || !y) hr.fail("offset", "must be [x, y] in millimetres from the cell centre");
      hole.offset_x = *x, hole.offset_y = *y;
    }
    if (std::fabs(hole.offset_x) + hole.diameter / 2 > spec.module_w / 2 + 1e-9 ||
        std::fabs(hole.offset_y) + hole.diameter / 2 > spec.module_h / 2 + 1e-9)
      r.fail_node(
          *a->get(i), path,
          "a hole of " + std::to_string(hole.diameter) + " mm at that offset does not fit in its " +
              std::to_string(static_cast<int>(spec.module_w)) + " x " +
              std::to_string(static_cast<int>(spec.module_h)) +
              " mm cell; holes must lie inside their cells (smaller, or nearer the centre)");
    spec.holes.push_back(hole);
  }
  spec.sheet_size = read_mm_pair(r, "sheet_size");
  if (spec.sheet_size) {
    double largest = 0;
    for (const HoleSpec& h : spec.holes) largest = std::max(largest, h.diameter);
    if ((*spec.sheet_size)[0] < largest + 2 * spec.edge_margin ||
        (*spec.sheet_size)[1] < largest + 2 * spec.edge_margin)
      r.fail("sheet_size", "a sheet must hold the largest opening (" +
                               std::to_string(static_cast<int>(largest)) +
                               " mm) within its margins (2 x " +
                               std::to_string(static_cast<int>(spec.edge_margin)) +
                               " mm); give a larger sheet_size");
  }
}

// Ordering: the spare share, pack size and lots of the schedules.
void read_ordering(TableReader& r, LayoutSpec& spec) {
  if (const toml::node* n = r.get("spare")) {
    const auto v = n->value<double>();
    if (!v || !std::isfinite(*v) || *v < 0 || *v > 10)
      r.fail("spare", "must be a share from 0 to 10, e.g. 0.05 for 5 % spare; not negative");
    spec.spare = *v;
  }
  spec.pack = read_int(r, "pack", 1, 1, 1000000);
  spec.lot_size = read_int(r, "lot_size", 0, 0, INT64_MAX);
  spec.lot_rows = read_int(r, "lot_rows", 0, 0, INT64_MAX);
  if (spec.lot_size && spec.lot_rows)
    r.fail("lot_rows", "give lots either by size (lot_size) or by rows (lot_rows), not both");
}

// layout.colours: exactly one "#rrggbb" per value, value 0 first.
void read_value_colours(TableReader& r, const Design& design, LayoutSpec& spec) {
  const size_t values = size_t{1} << design.curds.size();
  if (const toml::node* n = r.get("colours")) {
    const toml::array* a = n->as_array();
    if (!a) r.fail("colours", "must be an array of colours \"#rrggbb\", one per value");
    if (a->size() < values)
      r.fail("colours", "gives " + std::to_string(a->size()) + " colours for " +
                            std::to_string(values) + " values (2^" +
                            std::to_string(design.curds.size()) +
                            " curds); give one per value, value 0 first");
    if (a->size() > values)
      r.fail("colours", "gives " + std::to_string(a->size()) + " colours but there are only " +
                            std::to_string(values) + " values");
    for (size_t v = 0; v < a->size(); ++v) {
      const auto text = a->get(v)->value<std::string>();
      const auto colour = text ? parse_colour(*text) : std::nullopt;
      if (!colour)
        r.fail_node(*a->get(v), "layout.colours." + std::to_string(v),
                    "must be a colour written \"#rrggbb\"");
      spec.value_colours.push_back(colour);
    }
  }
}

std::optional<LayoutSpec> read_line_or_stack(TableReader& r, Design& design, LayoutSpec spec,
                                             bool field_given) {
  const size_t values = size_t{1} << design.curds.size();
  read_value_colours(r, design, spec);
  spec.scale = read_mm(r, "scale", 0, 1);
  spec.dpi = read_mm(r, "dpi", 150, 10);
  if (spec.kind == LayoutKind::blocks) {
    const toml::node* n = r.get("voxel");
    const toml::array* a = n ? n->as_array() : nullptr;
    std::array<double, 3> v{3000, 3000, 3000};
    if (n) {
      bool ok = a && a->size() == 3;
      for (size_t i = 0; ok && i < 3; ++i) {
        const auto x = a->get(i)->value<double>();
        ok = x && *x > 0 && *x <= 1e6;
        if (ok) v[i] = *x;
      }
      if (!ok) r.fail("voxel", "must be [width, depth, height] in millimetres, each above 0");
    }
    spec.module_w = v[0], spec.module_h = v[1], spec.voxel_h = v[2];
    return spec;
  }
  spec.module_w = read_mm(r, "bay", 600, 1);
  spec.module_h = read_mm(r, "height", 3000, 1);
  const auto origin =
      read_string(r, "origin", "\"bottom-left\" or \"bottom-right\"").value_or("bottom-left");
  if (origin != "bottom-left" && origin != "bottom-right")
    r.fail("origin", "must be \"bottom-left\" or \"bottom-right\" for a line");
  spec.origin = origin == "bottom-left" ? Corner::bottom_left : Corner::bottom_right;
  const toml::node* n = r.get("widths");
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a || a->size() != values)
    r.fail("widths", "must give one element width in mm per value (" + std::to_string(values) +
                         "), value 0 first; 0 leaves a bay empty");
  for (size_t v = 0; v < a->size(); ++v) {
    const auto x = a->get(v)->value<double>();
    if (!x || *x < 0 || *x > spec.module_w)
      r.fail_node(*a->get(v), "layout.widths." + std::to_string(v),
                  "must be a width from 0 to the bay (" +
                      std::to_string(static_cast<int>(spec.module_w)) + " mm)");
    spec.widths.push_back(*x);
  }
  if (r.get("length")) {
    const double length = read_mm(r, "length", 0, 1);
    spec.size = std::array<double, 2>{length, spec.module_h};
    const int64_t bays = static_cast<int64_t>(std::ceil(length / spec.module_w - 1e-9));
    // A larger field is a curd from which a segment of `bays` becomes the line.
    if (field_given && design.field.size[0] < bays)
      r.fail("length", "needs " + std::to_string(bays) + " bays but field.cells is " +
                           std::to_string(design.field.size[0]) +
                           "; leave field.cells out, or make it at least that large");
    if (!field_given) design.field.size[0] = bays;
  }
  return spec;
}

ParkElement read_park_element(TableReader& r, bool ground) {
  ParkElement e;
  e.type = read_string(r, "type", "a name such as \"tree\"").value_or(ground ? "white paving" : "");
  if (e.type.empty())
    r.fail("type", "is required: what the curd places, e.g. \"tree\", \"bench\", \"grey paving\"");
  const std::string form =
      ground ? "surface" : read_string(r, "form", "\"surface\" or \"object\"").value_or("object");
  if (form != "surface" && form != "object")
    r.fail("form",
           "must be \"surface\" (fills the cell, like paving) or \"object\" (stands in it)");
  e.surface = form == "surface";
  if (auto c = read_string(r, "colour", "a colour written \"#rrggbb\"")) {
    const auto colour = parse_colour(*c);
    if (!colour) r.fail("colour", "must be a colour written \"#rrggbb\"");
    e.colour = *colour;
  } else {
    e.colour = ground ? Rgb{242, 240, 234} : e.surface ? Rgb{140, 140, 140} : Rgb{58, 138, 79};
  }
  if (!e.surface) {
    const auto shape = read_string(r, "shape", "\"circle\" or \"rectangle\"").value_or("circle");
    if (shape != "circle" && shape != "rectangle")
      r.fail("shape", "must be \"circle\" or \"rectangle\"");
    e.round = shape == "circle";
    const auto size = read_mm_pair(r, "size", true);
    e.w = (*size)[0], e.h = e.round ? (*size)[0] : (*size)[1];
  }
  return e;
}

void read_park(TableReader& r, const Design& design, LayoutSpec& spec) {
  spec.clearance = read_mm(r, "clearance", 0, 0);
  if (const toml::node* g = r.get("ground")) {
    if (!g->as_table())
      r.fail("ground", "must be a table {type = \"white paving\", colour = \"#f2f0ea\"}");
    TableReader gr(*g->as_table(), "layout.ground", r.source(), {"type", "colour"});
    spec.ground = read_park_element(gr, true);
  }
  const toml::node* n = r.get("elements");
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a || a->size() != design.curds.size())
    r.fail("elements", "must give one element per curd (" + std::to_string(design.curds.size()) +
                           "), e.g. {type = \"tree\", form = \"object\", shape = \"circle\", size "
                           "= [2400, 2400]}");
  size_t objects = 0;
  for (size_t i = 0; i < a->size(); ++i) {
    const std::string path = "layout.elements." + std::to_string(i);
    if (!a->get(i)->as_table())
      r.fail_node(*a->get(i), path, "must be a table {type = ..., form = ...}");
    TableReader er(*a->get(i)->as_table(), path, r.source(),
                   {"type", "form", "shape", "size", "colour"});
    spec.park.push_back(read_park_element(er, false));
    objects += !spec.park.back().surface;
  }
  // Every object must fit in its slot when all the objects share one cell.
  const Rect cell{0, 0, spec.module_w, spec.module_h};
  const std::vector<Rect> slots = object_slots(cell, objects, spec.clearance);
  for (size_t i = 0; i < spec.park.size(); ++i) {
    const ParkElement& e = spec.park[i];
    if (e.surface || slots.empty()) continue;
    if (e.w > slots[0].w + 1e-9 || e.h > slots[0].h + 1e-9 || slots[0].w <= 0 || slots[0].h <= 0)
      r.fail_node(*a->get(i), "layout.elements." + std::to_string(i),
                  "a " + e.type + " of " + std::to_string(static_cast<int>(e.w)) + " x " +
                      std::to_string(static_cast<int>(e.h)) + " mm does not fit when " +
                      std::to_string(objects) + " objects share a " +
                      std::to_string(static_cast<int>(spec.module_w)) + " x " +
                      std::to_string(static_cast<int>(spec.module_h)) + " mm cell with " +
                      std::to_string(static_cast<int>(spec.clearance)) +
                      " mm clearance (each gets " +
                      std::to_string(static_cast<int>(std::max(0.0, slots[0].w))) + " x " +
                      std::to_string(static_cast<int>(std::max(0.0, slots[0].h))) +
                      " mm); use smaller elements, a larger cell or less clearance");
  }
}

std::optional<LayoutSpec> read_layout(TableReader& top, Design& design, bool field_given) {
  const toml::table* t = read_table(top, "layout");
  if (!t) return std::nullopt;
  LayoutSpec spec;
  std::string kind = "tile";
  if (const toml::node* k = t->get("kind")) {
    if (!k->is_string())
      top.fail_node(*k, "layout.kind", "must be \"tile\", \"paving\" or \"facade\"");
    kind = *k->value<std::string>();
  }
  std::vector<std::string> keys{"kind",         "combine",    "joint",     "origin",  "colours",
                                "joint_colour", "stage_grid", "highlight", "scale",   "dpi",
                                "spare",        "pack",       "lot_size",  "lot_rows"};
  std::string module_key, size_key;
  if (kind == "tile") {
    spec.kind = LayoutKind::tile;
    module_key = "tile", size_key = "size";
  } else if (kind == "paving") {
    spec.kind = LayoutKind::paving;
    module_key = "tile", size_key = "floor";
  } else if (kind == "facade" || kind == "façade") {
    spec.kind = LayoutKind::facade;
    module_key = "panel", size_key = "wall";
    keys.insert(keys.end(), {"openings", "mask"});
  } else if (kind == "perforation") {
    spec.kind = LayoutKind::perforation;
    module_key = "cell", size_key = "sheet";
    keys.insert(keys.end(), {"holes", "thickness", "min_diameter", "min_bridge", "edge_margin",
                             "fix", "chord_tolerance", "sheet_size"});
    keys.erase(std::find(keys.begin(), keys.end(), "joint"));
  } else if (kind == "rhythm") {
    spec.kind = LayoutKind::rhythm;
    keys = {"kind",      "bay",   "height", "length", "widths", "colours",  "origin",
            "highlight", "scale", "dpi",    "spare",  "pack",   "lot_size", "lot_rows"};
  } else if (kind == "blocks") {
    spec.kind = LayoutKind::blocks;
    keys = {"kind", "voxel", "colours", "scale", "dpi", "spare", "pack", "lot_size", "lot_rows"};
  } else if (kind == "park") {
    spec.kind = LayoutKind::park;
    module_key = "cell", size_key = "area";
    keys.insert(keys.end(), {"elements", "ground", "clearance"});
    keys.erase(std::find(keys.begin(), keys.end(), "joint"));
  } else {
    top.fail_node(*t->get("kind"), "layout.kind",
                  "unknown element kind \"" + kind +
                      "\"; allowed: \"tile\", \"paving\", \"facade\", \"perforation\", \"park\", "
                      "\"rhythm\", \"blocks\"");
  }
  if (!module_key.empty()) keys.push_back(module_key);
  if (!size_key.empty()) keys.push_back(size_key);
  TableReader r(*t, "layout", top.source(), keys);
  read_ordering(r, spec);
  const int dimension = spec.kind == LayoutKind::rhythm   ? 1
                        : spec.kind == LayoutKind::blocks ? 3
                                                          : 2;
  if (design.lattice.dimension != dimension)
    r.fail("kind", "a " + kind + " layout needs a " + std::to_string(dimension) +
                       "-D lattice; this one is " + std::to_string(design.lattice.dimension) +
                       "-D");
  if (spec.kind == LayoutKind::rhythm || spec.kind == LayoutKind::blocks)
    return read_line_or_stack(r, design, spec, field_given);

  const auto combine = read_string(r, "combine", "\"mix\" or \"keep\"").value_or("mix");
  if (combine == "mix")
    spec.combine = Combine::mix;
  else if (combine == "keep")
    spec.combine = Combine::keep;
  else
    r.fail("combine",
           "must be \"mix\" (a + b = c) or \"keep\" (a + b = ab), not \"" + combine + "\"");

  const auto module = read_mm_pair(r, module_key);
  if (module) spec.module_w = (*module)[0], spec.module_h = (*module)[1];
  spec.joint = spec.kind == LayoutKind::perforation ? 0 : read_mm(r, "joint", 0, 0);
  if (spec.joint >= std::min(spec.module_w, spec.module_h))
    r.fail("joint", "must be narrower than the " + module_key + " (" +
                        std::to_string(static_cast<int>(std::min(spec.module_w, spec.module_h))) +
                        " mm)");
  spec.size =
      read_mm_pair(r, size_key, spec.kind != LayoutKind::tile && spec.kind != LayoutKind::park);

  const auto origin = read_string(r, "origin", "a corner").value_or("bottom-left");
  if (origin == "bottom-left")
    spec.origin = Corner::bottom_left;
  else if (origin == "bottom-right")
    spec.origin = Corner::bottom_right;
  else if (origin == "top-left")
    spec.origin = Corner::top_left;
  else if (origin == "top-right")
    spec.origin = Corner::top_right;
  else
    r.fail("origin", "must be \"bottom-left\", \"bottom-right\", \"top-left\" or \"top-right\"");

  read_value_colours(r, design, spec);
  if (auto c = read_string(r, "joint_colour", "a colour written \"#rrggbb\"")) {
    const auto colour = parse_colour(*c);
    if (!colour) r.fail("joint_colour", "must be a colour written \"#rrggbb\"");
    spec.joint_colour = *colour;
  }
  spec.stage_grid = read_bool(r, "stage_grid", false);
  if (const toml::node* n = r.get("highlight")) {
    const toml::array* a = n->as_array();
    std::array<int64_t, 4> v{};
    bool ok = a && a->size() == 4;
    for (size_t i = 0; ok && i < 4; ++i) {
      const auto x = a->get(i)->value<int64_t>();
      ok = a->get(i)->is_integer() && x && *x >= (i < 2 ? 0 : 1);
      if (ok) v[i] = *x;
    }
    if (!ok) r.fail("highlight", "must be [x, y, width, height] in cells, a window to outline");
    spec.highlight = Box{{v[0], v[1], 0}, {v[2], v[3], 1}};
  }
  spec.scale = read_mm(r, "scale", 0, 1);
  spec.dpi = read_mm(r, "dpi", 150, 10);
  if (spec.dpi > 1200) r.fail("dpi", "must be from 10 to 1200");

  if (spec.kind == LayoutKind::facade) {
    if (const toml::node* n = r.get("openings")) {
      const toml::array* a = n->as_array();
      if (!a) r.fail("openings", "must be an array of [x, y, width, height] in millimetres");
      for (size_t i = 0; i < a->size(); ++i) {
        const toml::array* o = a->get(i)->as_array();
        const std::string path = "layout.openings." + std::to_string(i);
        std::array<double, 4> v{};
        bool ok = o && o->size() == 4;
        for (size_t k = 0; ok && k < 4; ++k) {
          const auto x = o->get(k)->value<double>();
          ok = x && std::isfinite(*x) && (k < 2 ? *x >= 0 : *x > 0);
          if (ok) v[k] = *x;
        }
        if (!ok)
          r.fail_node(*a->get(i), path,
                      "must be [x, y, width, height] in millimetres from the wall's bottom-left "
                      "corner, sizes above 0");
        const Rect rect{v[0], v[1], v[2], v[3]};
        if (rect.right() > (*spec.size)[0] + 1e-6 || rect.top() > (*spec.size)[1] + 1e-6)
          r.fail_node(*a->get(i), path,
                      "lies outside the wall of " +
                          std::to_string(static_cast<int>((*spec.size)[0])) + " x " +
                          std::to_string(static_cast<int>((*spec.size)[1])) + " mm");
        spec.openings.push_back(rect);
      }
    }
    spec.mask = read_string(r, "mask", "the path of an image").value_or("");
  }

  if (spec.kind == LayoutKind::perforation) read_perforation(r, design, spec);
  if (spec.kind == LayoutKind::park) read_park(r, design, spec);

  if (spec.size) {
    const auto cells = elements_to_cover(spec);
    // A larger field is a curd from which a segment of `cells` becomes the floor or wall.
    if (field_given && (design.field.size[0] < cells[0] || design.field.size[1] < cells[1]))
      r.fail(size_key, "needs " + std::to_string(cells[0]) + " x " + std::to_string(cells[1]) +
                           " elements but field.cells is " + std::to_string(design.field.size[0]) +
                           " x " + std::to_string(design.field.size[1]) +
                           "; leave field.cells out, or make it at least that large");
    if (!field_given) {
      design.field.size[0] = cells[0];
      design.field.size[1] = cells[1];
    }
  }
  return spec;
}

// Applies "a.b.0.c=VALUE" to the document.
void apply_override(toml::table& doc, const std::string& assignment) {
  const auto eq = assignment.find('=');
  const std::string key = assignment.substr(0, eq);
  if (eq == std::string::npos || key.empty())
    throw InputError(SourceLocation{"--set", 0, 0, key},
                     "expects KEY=VALUE, e.g. --set lattice.mode=exact");
  const std::string value = assignment.substr(eq + 1);
  const std::string source = "--set " + key;
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + value, source);
  } catch (const toml::parse_error&) {
    parsed = toml::parse("v = \"\"", source);  // a bare word is a string
    parsed.insert_or_assign("v", value);
  }
  const toml::node& v = *parsed.get("v");

  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    const size_t dot = key.find('.', start);
    parts.push_back(key.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  toml::node* at = &doc;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    const std::string& part = parts[i];
    if (auto* t = at->as_table()) {
      if (!t->get(part)) {
        const bool next_is_index = std::all_of(parts[i + 1].begin(), parts[i + 1].end(), ::isdigit);
        if (next_is_index)
          throw InputError(SourceLocation{"--set", 0, 0, key}, "'" + part + "' has no such entry");
        t->insert_or_assign(part, toml::table{});
      }
      at = t->get(part);
    } else if (auto* a = at->as_array()) {
      size_t idx = 0;
      auto [p, ec] = std::from_chars(part.data(), part.data() + part.size(), idx);
      if (ec != std::errc() || p != part.data() + part.size() || idx >= a->size())
        throw InputError(SourceLocation{"--set", 0, 0, key},
                         "index '" + part + "' is out of range; the array has " +
                             std::to_string(a->size()) + " entries (from 0)");
      at = a->get(idx);
    } else {
      throw InputError(SourceLocation{"--set", 0, 0, key},
                       "'" + part + "' is not a table or array");
    }
  }
  const std::string& last = parts.back();
  if (auto* t = at->as_table()) {
    v.visit([&](auto&& x) { t->insert_or_assign(last, x); });
  } else if (auto* a = at->as_array()) {
    size_t idx = 0;
    auto [p, ec] = std::from_chars(last.data(), last.data() + last.size(), idx);
    if (ec != std::errc() || idx >= a->size())
      throw InputError(SourceLocation{"--set", 0, 0, key}, "index '" + last + "' is out of range");
    v.visit([&](auto&& x) { a->replace(a->cbegin() + static_cast<ptrdiff_t>(idx), x); });
  } else {
    throw InputError(SourceLocation{"--set", 0, 0, key}, "cannot set a key inside a value");
  }
}

toml::table parse_toml(std::string_view text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(SourceLocation{source, static_cast<int>(e.source().begin.line),
                                    static_cast<int>(e.source().begin.column), ""},
                     "not valid TOML: " + std::string(e.description()));
  }
}

}  // namespace

Recipe parse_recipe(std::string_view text, const std::string& source,
                    const std::vector<std::string>& overrides) {
  toml::table doc = parse_toml(text, source);
  Source where{source, {}};
  for (const auto& o : overrides) {
    apply_override(doc, o);
    where.overridden.push_back(o.substr(0, o.find('=')));
  }

  TableReader top(doc, "", where,
                  {"name", "description", "seed", "lattice", "field", "curds", "layout"});
  Recipe recipe;
  recipe.design.name = read_string(top, "name").value_or("untitled");
  recipe.description = read_string(top, "description").value_or("");
  recipe.seed = static_cast<uint64_t>(read_int(top, "seed", 1, 0, INT64_MAX));
  Lattice lattice = read_lattice(top);
  recipe.design.curds = read_curds(top, lattice);
  check_size(top, lattice);
  check_exact(top, lattice, recipe.design.curds);
  recipe.design.lattice = lattice;
  recipe.design.field = read_field(top, lattice, recipe.window);
  const toml::table* field_table = doc.get("field") ? doc.get("field")->as_table() : nullptr;
  recipe.layout = read_layout(top, recipe.design, field_table && field_table->get("cells"));
  if (recipe.layout && recipe.layout->size && !recipe.window) {
    // The floor is laid from a segment of its own size; by default the one at the origin.
    const auto need = elements_to_cover(*recipe.layout);
    if (need[0] != recipe.design.field.size[0] || need[1] != recipe.design.field.size[1]) {
      Box segment;
      segment.size = {need[0], need[1], 1};
      recipe.window = segment;
    }
  }
  if (recipe.window && !recipe.design.field.contains(*recipe.window)) {
    std::string size;
    for (int d = 0; d < lattice.dimension; ++d)
      size += (d ? " x " : "") + std::to_string(recipe.design.field.size[d]);
    top.fail_node(*field_table->get("window"), "field.window",
                  "must lie inside the field of " + size + " cells (origin + size <= field)");
  }
  if (recipe.window && recipe.layout && recipe.layout->size) {
    const auto need = elements_to_cover(*recipe.layout);
    if (recipe.window->size[0] != need[0] || recipe.window->size[1] != need[1])
      top.fail_node(*field_table->get("window"), "field.window",
                    "must be " + std::to_string(need[0]) + " x " + std::to_string(need[1]) +
                        " cells, the elements of the layout's floor, wall, sheet or line");
  }
  return recipe;
}

std::string recipe_text_with(std::string_view text, const std::string& source,
                             const std::vector<std::string>& overrides) {
  toml::table doc = parse_toml(text, source);
  for (const auto& o : overrides) apply_override(doc, o);
  std::ostringstream out;
  out << doc << "\n";
  return out.str();
}

Box parse_window(const std::string& text, const Design& design) {
  const int E = design.lattice.dimension;
  const char* form = E == 1 ? "X,W" : E == 2 ? "X,Y,W,H" : "X,Y,Z,W,H,D";
  std::vector<int64_t> v;
  for (size_t start = 0; start <= text.size();) {
    size_t comma = text.find(',', start);
    if (comma == std::string::npos) comma = text.size();
    int64_t x = 0;
    auto [p, ec] = std::from_chars(text.data() + start, text.data() + comma, x);
    if (ec != std::errc() || p != text.data() + comma)
      throw InputError(SourceLocation{"--window", 0, 0, ""},
                       "'" + text + "' is not " + form + " (whole numbers of cells)");
    v.push_back(x);
    start = comma + 1;
  }
  if (static_cast<int>(v.size()) != 2 * E)
    throw InputError(
        SourceLocation{"--window", 0, 0, ""},
        "a " + std::to_string(E) + "-D lattice takes a window " + form + ", not '" + text + "'");
  Box box;
  for (int d = 0; d < E; ++d) {
    box.origin[d] = v[d];
    box.size[d] = v[E + d];
  }
  if (!design.field.contains(box) || box.cells() == 0 || box.size[0] < 1 || box.size[1] < 1 ||
      box.size[2] < 1) {
    std::string field;
    for (int d = 0; d < E; ++d) field += (d ? " x " : "") + std::to_string(design.field.size[d]);
    throw InputError(SourceLocation{"--window", 0, 0, ""},
                     "'" + text + "' must lie inside the field of " + field +
                         " cells (origin >= 0, sizes >= 1)");
  }
  return box;
}

}  // namespace curdle
