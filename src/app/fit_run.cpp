#include "app/fit_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "app/chain_reading.h"
#include "app/measure_run.h"
#include "app/picture_cells.h"
#include "app/run.h"
#include "app/toml_text.h"
#include "curdle/error.h"
#include "curdle/measure.h"
#include "export/report/measure_files.h"
#include "io/atomic_file.h"
#include "io/bounded_file.h"
#include "io/cells_csv_reader.h"

namespace curdle::app {
namespace {
constexpr uint64_t kMaxCells = uint64_t{1} << 26;  // a cells.csv's, as many as a picture's
constexpr uint64_t kMaxCsvBytes = uint64_t{2} << 30;
// Below this chance of a statistic as large under the fitted curd, no curd explains it.
constexpr double kExplained = 1e-3;

// A file's name as a comment's text: one line, whatever the name holds.
std::string comment_text(const std::string& s) {
  std::string line;
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    line += c < 0x20 || c == 0x7F || c >= 0x80 ? '?' : ch;
  }
  return line;
}

std::string recipe_text(const FittedRecipe& f, const std::string& source) {
  std::string cells;
  for (int d = 0; d < f.lattice.dimension; ++d)
    cells += (d ? ", " : "") + std::to_string(f.size[static_cast<size_t>(d)]);
  std::string t;
  if (f.recipe_is_chain)
    t += fmt::format(
        "# Fitted by `curdle fit` to {}: the Markov chain under which the finest cells' states\n"
        "# are most likely, the coarser cells' states summed over (maximum likelihood by EM).\n",
        comment_text(source));
  else
    t += fmt::format(
        "# Fitted by `curdle fit` to {}: per-stage probabilities under which each stage's\n"
        "# occupied cells branch, from the stage before, as the picture's do (extinction and the\n"
        "# survival of every occupied cell included).\n",
        comment_text(source));
  if (f.chain)
    for (const Reading& reading : f.chain->readings)
      t += fmt::format(
          "# Read as {}: log L {:.1f}, {} parameters, BIC {:.1f}{}\n", reading.what,
          reading.log_likelihood, reading.parameters, reading.bic,
          reading.name == f.chain->supported && f.chain->readings.size() > 1 ? " (supported)" : "");
  if (f.pixels_per_cell > 1)
    t += fmt::format("# The picture's cells are {0} x {0} pixels: fitted in cells.\n",
                     f.pixels_per_cell);
  if (f.by_colour) t += "# Curds told apart by the picture's colours.\n";
  for (const std::string& w : f.warnings) t += "# WARNING: " + comment_text(w) + "\n";
  t += fmt::format(
      "name = {}\nseed = 1\n\n[lattice]\nbase = {}\ndimension = {}\nstages = {}\n"
      "mode = \"canonical\"\n\n[field]\ncells = [{}]\n",
      toml_quoted(f.name), f.lattice.base, f.lattice.dimension, f.lattice.stages, cells);
  if (f.recipe_is_chain) return t + chain_recipe_toml(*f.chain, f.lattice.stages);
  for (const FittedCurd& c : f.curds) {
    std::string p;
    for (const StageFit& s : c.fit.stages)
      p += (p.empty() ? "" : ", ") + probability_text(s.probability);
    t += fmt::format("\n[[curds]]\nname = {}\nprobabilities = [{}]\n", toml_quoted(c.name), p);
    if (!c.colour.empty()) t += fmt::format("colour = {}\n", toml_quoted(c.colour));
  }
  return t;
}

// What the test says of a curd: a warning when no curd at these stages explains it, naming
// the stages that fail and which way, or when it has too few cells to tell.
std::vector<std::string> warnings_of(const FittedCurd& c) {
  const CurdFit& fit = c.fit;
  if (fit.degrees == 0)
    return {
        fmt::format("curd '{}' has too few cells ({} at the last stage) to test whether a "
                    "curd explains it; its probabilities are a guess",
                    c.name, fit.stages.back().measured)};
  if (fit.p_value >= kExplained) return {};
  std::string even, uneven;
  for (const StageFit& s : fit.stages) {
    if (s.degrees == 0 || s.p_value >= kExplained) continue;
    std::string& list = s.dispersion < 0 ? even : uneven;
    list += (list.empty() ? "" : ", ") + std::to_string(s.stage);
  }
  std::string how;
  if (!even.empty())
    how += "at stage " + even +
           " its cells branch more evenly than any curd's (too regular: stripes, a grid, a "
           "checkerboard)";
  if (!uneven.empty())
    how += (how.empty() ? "at stage " : "; at stage ") + uneven +
           " more unevenly (too clustered: a gradient, a disk, a photograph)";
  if (how.empty()) how = "no single stage fails alone, but together they do";
  return {
      fmt::format("no curd at these stages explains curd '{}' (chi-square {:.1f} on {} "
                  "degrees of freedom, p = {:.2g}): {}",
                  c.name, fit.chi_square, fit.degrees, fit.p_value, how)};
}

// A curd with no cell, or with every cell, has nothing to fit: refused, saying which.
void check_figure(const std::vector<bool>& cells, const std::string& curd,
                  const std::string& source) {
  const auto n = static_cast<size_t>(std::count(cells.begin(), cells.end(), true));
  const std::string what = curd == "figure" ? "the picture" : "curd '" + curd + "'";
  if (n == 0)
    throw InputError(parameter("source"),
                     what + " in " + comment_text(source) +
                         " has no cell of figure (a blank picture, or a threshold that keeps "
                         "none): there is nothing to fit");
  if (n == cells.size())
    throw InputError(parameter("source"),
                     what + " in " + comment_text(source) +
                         " is figure in every cell (p = 1 at every stage): there is nothing to "
                         "fit; a picture needs figure and ground");
}

// The recipe's text, checked: it must read back as written (a fitted recipe curdle refuses is
// a bug here).
FittedRecipe finish(FittedRecipe f, const std::string& source) {
  for (const FittedCurd& c : f.curds)
    for (std::string& w : warnings_of(c)) f.warnings.push_back(std::move(w));
  if (f.chain && !f.recipe_is_chain && f.chain->supported == "chain")
    f.warnings.push_back(fmt::format(
        "the cells are better read as {} (BIC lower by {:.1f} than as these curds): fit it with "
        "--states {}",
        f.chain->readings[0].what, f.chain->margin, f.chain->states.size()));
  f.toml = recipe_text(f, std::filesystem::path(source).filename().string());
  RunRequest check;
  check.recipe_text = f.toml;
  check.recipe_path = f.name + ".toml";
  (void)resolve_run(check);
  return f;
}

// The recipe's name: the source's stem, in letters, digits, '-' and '_'.
std::string fitted_name(const std::string& source) {
  std::string name = std::filesystem::path(source).stem().string() + "-fit";
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '-';
  return name;
}

// A picture's values (top row first) with y up from its bottom row, as the lattice counts.
std::vector<uint8_t> upright(const std::vector<uint16_t>& values, int64_t width, int64_t height) {
  std::vector<uint8_t> out(static_cast<size_t>(width * height));
  for (int64_t y = 0; y < height; ++y)
    for (int64_t x = 0; x < width; ++x)
      out[static_cast<size_t>(y * width + x)] =
          static_cast<uint8_t>(values[static_cast<size_t>((height - 1 - y) * width + x)]);
  return out;
}

// The overlaid curds' values read as one chain, to compare: the values that occur, numbered
// 0, 1, ... in order (0 the ground), as its states.
std::optional<ChainReading> compared_chain(const Lattice& l, const Box& view,
                                           const std::vector<uint8_t>& values, uint64_t max_memory,
                                           std::vector<std::string>& warnings) {
  std::vector<uint8_t> tone_of(256, 0);
  std::vector<bool> seen(256, false);
  for (const uint8_t v : values) seen[v] = true;
  uint8_t next = seen[0] ? 1 : 0;
  for (size_t v = 1; v < seen.size(); ++v)
    if (seen[v]) tone_of[v] = next++;
  ChainRequest q;
  q.lattice = l;
  q.view = view;
  q.tones.reserve(values.size());
  for (const uint8_t v : values) q.tones.push_back(tone_of[v]);
  q.intervals = false;
  q.max_memory = max_memory;
  try {
    return read_as_chain(std::move(q));
  } catch (const ResourceLimitError& e) {
    // The overlay is what was asked for: it stands, and the comparison is said to be missing.
    warnings.push_back(std::string("the cells were not also read as one chain: ") + e.what());
    return std::nullopt;
  }
}

[[noreturn]] void refuse_chain_options_without_states() {
  throw InputError(parameter("stage_wise"),
                   "--stage-wise and --wheys shape a Markov chain: give --states S with them (or a "
                   "cells.csv of a Markov curd)");
}

FittedRecipe fit_picture_chain(const LuminanceImage& image, const FitRequest& r, FittedRecipe f) {
  const PictureCells picture = picture_tones(image, r.states + 1, r.cell_pixels);
  f.pixels_per_cell = picture.pixels_per_cell;
  f.by_colour = picture.by_colour;
  f.size = {picture.width, picture.height, 1};
  ChainRequest q;
  q.lattice = f.lattice;
  q.view = Box{{0, 0, 0}, f.size};
  q.tones = upright(picture.values, picture.width, picture.height);
  std::vector<bool> present(static_cast<size_t>(r.states) + 1, false);
  for (const uint8_t t : q.tones) present[t] = true;
  const auto tones = std::count(present.begin(), present.end(), true);
  if (tones < r.states + 1)
    throw InputError(parameter("states"),
                     fmt::format("{} has {} tone{} where --states {} needs {} (the lightest is "
                                 "the ground, dead): give --states {}",
                                 comment_text(r.source), tones, tones == 1 ? "" : "s", r.states,
                                 r.states + 1, std::max<int64_t>(1, tones - 1)));
  q.colours.assign(picture.curd_colours.begin() + 1, picture.curd_colours.end());
  q.stage_wise = r.stage_wise;
  q.wheys = r.wheys;
  q.max_memory = r.max_memory;
  f.chain = read_as_chain(std::move(q));
  f.recipe_is_chain = true;
  return finish(f, r.source);
}

FittedRecipe fit_cells_file(const FitRequest& r) {
  // A curd field as curdle writes it: the curds and their cells are the file's own.
  const CellsTable table =
      parse_cells_csv(read_bounded_text(r.source, "the cells file",
                                        "a cells.csv as curdle generate writes it", kMaxCsvBytes),
                      kMaxCells);
  FittedRecipe f;
  f.name = fitted_name(r.source);
  f.lattice = Lattice{r.base, table.dimension, r.stages, Mode::canonical};
  check_fit_lattice(f.lattice);  // the file's dimension is known only now
  f.size = table.box.size;
  // The file's cells keep their place on the lattice: a window's boxes align to the lattice
  // origin, as the report counts them.
  const size_t chains = static_cast<size_t>(std::count_if(
      table.states.begin(), table.states.end(), [](const auto& s) { return !s.empty(); }));
  // Plain curds' values, as tones (at most 4 curds: 16 tones).
  const bool toned = chains == 0 && table.curds.size() <= 4;
  std::vector<uint8_t> values(toned ? table.cells[0].size() : 0, 0);
  for (size_t c = 0; c < (toned ? table.curds.size() : 0); ++c)
    for (size_t i = 0; i < values.size(); ++i)
      values[i] |= static_cast<uint8_t>(table.cells[c][i] << c);
  if (chains > 0 || r.states > 0) {
    ChainRequest q;
    q.lattice = f.lattice;
    q.view = table.box;
    q.stage_wise = r.stage_wise;
    q.wheys = r.wheys;
    q.max_memory = r.max_memory;
    if (chains > 0) {
      if (table.curds.size() != 1)
        throw InputError(parameter("source"),
                         fmt::format("{} holds {} curds, {} of them Markov: fit takes a file of "
                                     "one Markov curd, or of plain curds only",
                                     comment_text(r.source), table.curds.size(), chains));
      q.curd = table.curds[0];
      q.tones = table.state_cells[0];
      q.states = table.states[0];
      for (size_t s = 0; s < q.states.size(); ++s)
        if (q.states[s].empty()) q.states[s] = "state-" + std::to_string(s + 1);
    } else {
      if (!toned)
        throw InputError(parameter("states"),
                         fmt::format("{} holds {} curds: --states reads the values of at most 4 "
                                     "as a chain's states",
                                     comment_text(r.source), table.curds.size()));
      q.tones = values;
      const int most = *std::max_element(values.begin(), values.end());
      if (most > r.states)
        throw InputError(parameter("states"),
                         fmt::format("{} has values up to {}: --states {} reads values 0 to {} "
                                     "as states (0 the ground); give --states {}",
                                     comment_text(r.source), most, r.states, r.states, most));
      q.states.assign(static_cast<size_t>(r.states), "");
      for (int s = 0; s < r.states; ++s)
        q.states[static_cast<size_t>(s)] = "value-" + std::to_string(s + 1);
    }
    f.chain = read_as_chain(std::move(q));
    f.recipe_is_chain = true;
    return finish(f, r.source);
  }
  if (r.stage_wise || r.wheys) refuse_chain_options_without_states();
  for (size_t c = 0; c < table.curds.size(); ++c) {
    FittedCurd curd;
    curd.name = table.curds[c];
    check_figure(table.cells[c], curd.name, r.source);
    curd.fit = fit_curd(f.lattice, table.box, table.cells[c]);
    f.curds.push_back(std::move(curd));
  }
  if (toned && table.curds.size() >= 2)
    f.chain = compared_chain(f.lattice, table.box, values, r.max_memory, f.warnings);
  return finish(f, r.source);
}

}  // namespace

std::string probability_text(double p) { return fmt::format("{:.4f}", p); }

void check_fit_options(const FitRequest& r) {
  check_base(r.base);
  if (r.stages < 1 || r.stages > 30)
    throw InputError(parameter("stages"), "must be from 1 to 30, not " + std::to_string(r.stages));
  if (r.curds < 1 || r.curds > 4)
    throw InputError(parameter("curds"),
                     "must be from 1 to 4 (the picture is quantised to 2^n values), not " +
                         std::to_string(r.curds));
  if (r.states < 0 || r.states > 15)
    throw InputError(parameter("states"),
                     "must be from 1 to 15 living states (a picture's S + 1 tones), or 0 for "
                     "overlaid curds, not " +
                         std::to_string(r.states));
  if (r.cell_pixels < 0 || r.cell_pixels > 4096)
    throw InputError(
        parameter("cell_pixels"),
        "must be from 1 to 4096 pixels, or 0 to find it, not " + std::to_string(r.cell_pixels));
  check_fit_lattice(Lattice{r.base, 2, r.stages, Mode::canonical});
}

void check_fit_lattice(const Lattice& l) {
  // b^(E K) cells to a root must fit the recipe's limit, or the counts overflow.
  if (l.path_bits() > kMaxPathBits + 1e-9)
    throw InputError(
        parameter("stages"),
        fmt::format("with base {} in {}-D, {} stages make {:.0f} bits of cells to a "
                    "root; at most {}: at most {} stages with this base",
                    l.base, l.dimension, l.stages, l.path_bits(), kMaxPathBits,
                    static_cast<int>(kMaxPathBits / (l.dimension * std::log2(l.base)))));
}

FittedRecipe run_fit(const FitRequest& r) {
  check_fit_options(r);
  if (std::filesystem::path(r.source).extension() == ".csv") return fit_cells_file(r);
  if ((r.stage_wise || r.wheys) && r.states == 0) refuse_chain_options_without_states();
  return fit_picture(read_picture(r.source, r.max_memory), r);
}

FittedRecipe fit_picture(const LuminanceImage& image, const FitRequest& r) {
  check_fit_options(r);
  FittedRecipe f;
  f.name = fitted_name(r.source);
  f.lattice = Lattice{r.base, 2, r.stages, Mode::canonical};
  // One shade everywhere (blank white, all black): no figure and ground to tell apart.
  const auto [darkest, lightest] =
      std::minmax_element(image.luminance.begin(), image.luminance.end());
  if (darkest == image.luminance.end() || *darkest == *lightest)
    throw InputError(parameter("source"),
                     comment_text(r.source) +
                         " is one shade in every pixel: no figure to fit (a picture needs "
                         "figure and ground)");
  if (r.states > 0) return fit_picture_chain(image, r, std::move(f));
  // A preview draws each cell as k x k pixels: fitted in cells, not pixels.
  const PictureCells picture = picture_cells(image, r.curds, r.cell_pixels);
  f.pixels_per_cell = picture.pixels_per_cell;
  f.by_colour = picture.by_colour;
  const int64_t width = picture.width, height = picture.height;
  f.size = {width, height, 1};
  const Box field{{0, 0, 0}, f.size};
  const std::vector<uint8_t> values = upright(picture.values, width, height);
  for (int c = 0; c < r.curds; ++c) {
    std::vector<bool> cells(values.size());
    for (size_t i = 0; i < values.size(); ++i) cells[i] = values[i] >> c & 1;
    FittedCurd curd;
    curd.name = r.curds == 1 ? "figure" : "curd-" + std::to_string(c + 1);
    curd.colour = picture.curd_colours[static_cast<size_t>(c)];
    check_figure(cells, curd.name, r.source);
    curd.fit = fit_curd(f.lattice, field, cells);
    f.curds.push_back(std::move(curd));
  }
  if (r.curds >= 2) f.chain = compared_chain(f.lattice, field, values, r.max_memory, f.warnings);
  return finish(f, r.source);
}

std::string write_fitted_recipe(const FittedRecipe& fitted, const std::string& out) {
  namespace fs = std::filesystem;
  const fs::path path =
      out.empty() ? fs::path("curdle-out") / (fitted.name + ".toml") : fs::path(out);
  if (path.has_parent_path()) make_output_dir(path.parent_path());
  write_file(path, [&](std::ostream& s) { s << fitted.toml; });
  return fs::absolute(path).lexically_normal().string();
}

}  // namespace curdle::app
