#include "app/fit_run.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "app/measure_run.h"
#include "app/run.h"
#include "curdle/error.h"
#include "curdle/measure.h"
#include "export/atomic_file.h"
#include "export/cells_csv_reader.h"
#include "export/measure_files.h"

namespace curdle::app {
namespace {
constexpr uint64_t kMaxCells = uint64_t{1} << 26;  // a cells.csv's, as many as a picture's
constexpr uint64_t kMaxCsvBytes = uint64_t{2} << 30;

// A TOML basic string: quotes, backslashes and control characters escaped, so that no name
// (a curd's, from a cells.csv) can end the string and write keys of its own.
std::string toml_quoted(const std::string& s) {
  std::string q = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\')
      q += '\\', q += ch;
    else if (c < 0x20 || c == 0x7F)
      q += fmt::format("\\u{:04X}", c);
    else
      q += ch;
  }
  return q + '"';
}

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
  std::string t = fmt::format(
      "# Fitted by `curdle fit` to {}: per-stage probabilities whose expected box counts, with\n"
      "# extinction, match the picture's occupied cells at every stage.\n"
      "name = {}\nseed = 1\n\n[lattice]\nbase = {}\ndimension = {}\nstages = {}\n"
      "mode = \"canonical\"\n\n[field]\ncells = [{}]\n",
      comment_text(source), toml_quoted(f.name), f.lattice.base, f.lattice.dimension,
      f.lattice.stages, cells);
  for (const FittedCurd& c : f.curds) {
    std::string p;
    for (const StageFit& s : c.stages)
      p += (p.empty() ? "" : ", ") + probability_text(s.probability);
    t += fmt::format("\n[[curds]]\nname = {}\nprobabilities = [{}]\n", toml_quoted(c.name), p);
    if (!c.colour.empty()) t += fmt::format("colour = {}\n", toml_quoted(c.colour));
  }
  return t;
}

// The recipe's text, checked: it must read back as written (a fitted recipe curdle refuses is
// a bug here).
FittedRecipe finish(FittedRecipe f, const std::string& source) {
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
  FittedRecipe f;
  f.name = fitted_name(r.source);
  if (std::filesystem::path(r.source).extension() == ".csv") {
    // A curd field as curdle writes it: the curds and their cells are the file's own.
    const CellsTable table =
        parse_cells_csv(read_bounded_text(r.source, "the cells file",
                                          "a cells.csv as curdle generate writes it", kMaxCsvBytes),
                        kMaxCells);
    f.lattice = Lattice{r.base, table.dimension, r.stages, Mode::canonical};
    check_fit_lattice(f.lattice);  // the file's dimension is known only now
    f.size = table.box.size;
    const Box field{{0, 0, 0}, table.box.size};
    for (size_t c = 0; c < table.curds.size(); ++c) {
      FittedCurd curd;
      curd.name = table.curds[c];
      curd.stages =
          fit_probabilities(f.lattice, field, occupied_cells(f.lattice, field, table.cells[c]));
      f.curds.push_back(std::move(curd));
    }
    return finish(f, r.source);
  }
  return fit_picture(read_picture(r.source, r.max_memory), r);
}

FittedRecipe fit_picture(const LuminanceImage& image, const FitRequest& r) {
  check_fit_options(r);
  FittedRecipe f;
  f.name = fitted_name(r.source);
  f.lattice = Lattice{r.base, 2, r.stages, Mode::canonical};
  f.size = {image.width, image.height, 1};
  const int64_t width = image.width, height = image.height;
  std::vector<double> levels;
  const int values = 1 << r.curds;
  const ValueGrid grid = quantise(image.width, image.height, image.luminance, values, levels);
  const Box field{{0, 0, 0}, f.size};
  for (int c = 0; c < r.curds; ++c) {
    // Cells with the curd's bit, y up from the picture's bottom row.
    std::vector<bool> cells(static_cast<size_t>(width * height));
    for (int64_t y = 0; y < height; ++y)
      for (int64_t x = 0; x < width; ++x)
        cells[static_cast<size_t>(y * width + x)] =
            grid.values[static_cast<size_t>((height - 1 - y) * width + x)] >> c & 1;
    FittedCurd curd;
    curd.name = r.curds == 1 ? "figure" : "curd-" + std::to_string(c + 1);
    curd.colour = level_colour(levels[static_cast<size_t>(1) << c]);
    curd.stages = fit_probabilities(f.lattice, field, occupied_cells(f.lattice, field, cells));
    f.curds.push_back(std::move(curd));
  }
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
