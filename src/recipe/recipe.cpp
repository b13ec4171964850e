#include "recipe/recipe.h"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

#include "curdle/error.h"

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
    if (!field.contains(box) || box.cells() == 0)
      r.fail("window",
             "must lie inside the field (origin >= 0, size >= 1, origin + size <= field)");
    window = box;
  }
  return field;
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

}  // namespace

Recipe parse_recipe(std::string_view text, const std::string& source,
                    const std::vector<std::string>& overrides) {
  toml::table doc;
  try {
    doc = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(SourceLocation{source, static_cast<int>(e.source().begin.line),
                                    static_cast<int>(e.source().begin.column), ""},
                     "not valid TOML: " + std::string(e.description()));
  }
  Source where{source, {}};
  for (const auto& o : overrides) {
    apply_override(doc, o);
    where.overridden.push_back(o.substr(0, o.find('=')));
  }

  TableReader top(doc, "", where, {"name", "description", "seed", "lattice", "field", "curds"});
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
  return recipe;
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
