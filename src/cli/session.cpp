#include "cli/session.h"

#include <tbb/global_control.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "cli/progress.h"
#include "curdle/error.h"

namespace curdle::cli {

void add_common_options(CLI::App& c, CommonOptions& o) {
  c.add_option("recipe", o.recipe_path,
               "Recipe file (TOML), e.g. patterns/paper/fig3-two-curds.toml")
      ->required();
  c.add_option("--seed", o.seed, "Random seed, 0 to 2^64-1 (default: the recipe's `seed`, else 1)");
  c.add_option("--set", o.sets,
               "Override a recipe key: --set lattice.mode=exact, "
               "--set curds.0.probabilities='[\"1/2\",\"1/2\"]'")
      ->allow_extra_args(false);  // one value each time, so the recipe may follow
  c.add_option("--window", o.window,
               "Segment of the field in cells: X,Y,W,H (1-D X,W; 3-D X,Y,Z,W,H,D)");
  c.add_option("--threads", o.threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  c.add_option("--max-memory", o.max_memory,
               "Refuse work above this much memory, e.g. 8G "
               "(default: half the physical memory)");
}

uint64_t default_memory_limit() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || size <= 0) return uint64_t{8} << 30;
  return static_cast<uint64_t>(pages) * static_cast<uint64_t>(size) / 2;
}

uint64_t parse_bytes(const std::string& text, const std::string& option) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (...) {
    used = 0;
  }
  std::string unit = text.substr(used);
  for (auto& ch : unit) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  double scale = 0;
  if (unit.empty() || unit == "B")
    scale = 1;
  else if (unit == "K" || unit == "KB" || unit == "KIB")
    scale = 1024.0;
  else if (unit == "M" || unit == "MB" || unit == "MIB")
    scale = 1024.0 * 1024;
  else if (unit == "G" || unit == "GB" || unit == "GIB")
    scale = 1024.0 * 1024 * 1024;
  else if (unit == "T" || unit == "TB" || unit == "TIB")
    scale = 1024.0 * 1024 * 1024 * 1024;
  if (used == 0 || scale == 0 || !(value > 0) || !std::isfinite(value))
    throw InputError(
        SourceLocation{option, 0, 0, ""},
        "'" + text + "' is not a size; write a positive number with K, M, G or T, e.g. 8G");
  return static_cast<uint64_t>(value * scale);
}

std::string read_recipe_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(SourceLocation{path, 0, 0, ""},
                     std::string("cannot read the recipe: ") + std::strerror(errno));
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

Session open_session(const CommonOptions& o) {
  return make_session(read_recipe_file(o.recipe_path), o);
}

Session make_session(const std::string& recipe_text, const CommonOptions& o) {
  Session s;
  s.recipe_path = o.recipe_path;
  s.recipe = parse_recipe(recipe_text, o.recipe_path, o.sets);
  s.seed = s.recipe.seed;
  if (!o.seed.empty()) {
    auto [end, ec] = std::from_chars(o.seed.data(), o.seed.data() + o.seed.size(), s.seed);
    if (ec != std::errc() || end != o.seed.data() + o.seed.size())
      throw InputError(SourceLocation{"--seed", 0, 0, ""},
                       "'" + o.seed + "' is not a seed; a seed is a whole number from 0 to " +
                           std::to_string(UINT64_MAX));
  }
  s.view = s.recipe.design.field;
  if (s.recipe.window) s.view = *s.recipe.window;
  if (!o.window.empty()) s.view = parse_window(o.window, s.recipe.design);
  s.generate.max_memory_bytes =
      o.max_memory.empty() ? default_memory_limit() : parse_bytes(o.max_memory, "--max-memory");
  s.generate.memory_limit_hint = "raise the limit with --max-memory";
  return s;
}

std::string window_text(const Box& w, int dimension) {
  std::string text;
  for (int d = 0; d < dimension; ++d) text += std::to_string(w.origin[d]) + ",";
  for (int d = 0; d < dimension; ++d) text += std::to_string(w.size[d]) + (d + 1 < dimension ? "," : "");
  return text;
}

namespace {
std::string shell_quote(const std::string& word) {
  const bool plain = !word.empty() && word.find_first_not_of(
                                          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_-./,=:+@%") == std::string::npos;
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}
}  // namespace

std::string generate_command(const std::string& recipe_path, const std::vector<std::string>& sets,
                             uint64_t seed, const std::optional<Box>& window, int dimension) {
  std::string command = "curdle generate ";
  command += shell_quote(recipe_path);
  for (const std::string& set : sets) {
    command += " --set ";
    command += shell_quote(set);
  }
  command += " --seed ";
  command += std::to_string(seed);
  if (window) {
    command += " --window ";
    command += window_text(*window, dimension);
  }
  return command;
}

CurdField run_engine(const Session& s, int threads, bool show_progress) {
  std::optional<tbb::global_control> limit;
  if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, threads);
  Progress progress("curdling", show_progress);
  GenerateOptions options = s.generate;
  options.progress = [&](double f) { progress.update(f); };
  return curdle(s.recipe.design, s.seed, s.view, options);
}

}  // namespace curdle::cli
