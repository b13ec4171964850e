// Reading recipe TOML: one table at a time, with its allowed keys known up front so that an
// unknown key (often a misspelt required one) is reported first, with a did-you-mean; every
// error names the file, line, column and key, or the override that set the key.
#pragma once

#include <toml++/toml.h>

#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "curdle/curd.h"
#include "curdle/error.h"
#include "curdle/probability.h"
#include "recipe/recipe_files.h"

namespace curdle::reading {

std::string join(const std::vector<std::string>& items);

// Where the recipe came from: its file, the keys the command line overrode, and how the files
// it names are read (none: a recipe that names one is refused).
struct Source {
  std::string file;
  std::vector<std::string> overridden;  // dotted keys given with --set
  const RecipeFiles* files = nullptr;
};

SourceLocation locate(const Source& source, const toml::source_region& region,
                      const std::string& key);

// Reads one table whose allowed keys are known up front, so that an unknown key (often a
// misspelt required one) is reported before anything else.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string path, const Source& source,
              std::vector<std::string> allowed)
      : table_(table), path_(std::move(path)), source_(source), known_(std::move(allowed)) {
    reject_unknown();
  }

  // The key's node, or nullptr; either way the key counts as read (report_unused).
  const toml::node* get(const std::string& key) const {
    asked_.insert(key);
    return table_.get(key);
  }
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
  void reject_unknown() const;
  // After the readers have run: a key present that none of them asked for is an error, `why`
  // (as pbrt's ReportUnused), so that no key is accepted and then silently ignored.
  void report_unused(const std::string& why) const;
  // The allowed keys no reader asked for: a reader that lists a key it never reads.
  std::vector<std::string> never_asked() const;

  const Source& source() const { return source_; }

 private:
  const toml::table& table_;
  std::string path_;
  const Source& source_;
  std::vector<std::string> known_;
  mutable std::set<std::string> asked_;
};

int64_t read_int(TableReader& r, const std::string& key, int64_t fallback, int64_t lo, int64_t hi,
                 bool required = false);
std::optional<std::string> read_string(TableReader& r, const std::string& key,
                                       const std::string& allowed = "text");
// A name (a recipe's, a zone's, a park element's): a string of one line.
std::optional<std::string> read_name(TableReader& r, const std::string& key,
                                     const std::string& allowed = "text");
const toml::table* read_table(TableReader& r, const std::string& key);
std::optional<Rgb> parse_colour(std::string_view s);
// A colour written "#rrggbb", or the fallback when the key is absent.
std::optional<Rgb> read_colour(TableReader& r, const std::string& key);
Probability read_probability(const TableReader& r, const toml::node& n, const std::string& path);
// A number that is finite (no NaN or infinity), integer or floating; nothing otherwise.
std::optional<double> finite_number(const toml::node* node);
// A length in millimetres from `lo` to 10 km.
double read_mm(TableReader& r, const std::string& key, double fallback, double lo,
               bool required = false);
// [width, height] in millimetres, each from 1 mm to 10 km.
std::optional<std::array<double, 2>> read_mm_pair(TableReader& r, const std::string& key,
                                                  bool required = false);
bool read_bool(TableReader& r, const std::string& key, bool fallback);
// The recipe's seed, 0 to 2^64 - 1 (1 when absent). TOML integers stop at 2^63 - 1, so a larger
// seed is written as text: seed = "18446744073709551615"; text is taken for any seed.
uint64_t read_seed(TableReader& r);
// The most parts a dotted key or a table header may have; recipes use at most 4.
constexpr int kMostKeyParts = 64;

// The longest run of dot-separated parts outside strings and comments (a key or header; a
// number's decimal point counts as a part, which only overstates) and the line it ends on.
struct KeyDepth {
  int parts = 1;
  int line = 1;
};
KeyDepth deepest_key(std::string_view text);

// Parses TOML; InputError (naming the line) for invalid text or a key deeper than kMostKeyParts.
toml::table parse_toml(std::string_view text, const std::string& source);

}  // namespace curdle::reading
