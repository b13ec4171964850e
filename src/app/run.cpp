#include "app/run.h"

#include <sys/stat.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>

#include "curdle/error.h"
#include "io/bounded_file.h"
#include "io/bounded_image.h"
#include "site/drawing.h"
#include "site/reading_memory.h"

namespace curdle::app {

namespace {
constexpr uint64_t kMaxRecipeBytes = uint64_t{1} << 20;
constexpr int64_t kMaxDensitySide = 4096;
constexpr uint64_t kMaxDensityPixels = uint64_t{kMaxDensitySide} * kMaxDensitySide;

// The files a recipe names, beside it: regular files of bounded size, read whole, and refused
// before any parser sees them where reading them could take more than the run's memory limit.
class RecipeFolderFiles : public RecipeFiles {
 public:
  RecipeFolderFiles(std::string recipe_path, uint64_t max_memory, std::string hint)
      : recipe_path_(std::move(recipe_path)), max_memory_(max_memory), hint_(std::move(hint)) {}
  std::string read(const std::string& name, const SourceLocation& where,
                   size_t max_bytes) const override {
    const auto path = std::filesystem::path(recipe_path_).parent_path() / name;
    std::string bytes;
    try {
      bytes = read_bounded_text(path.string(), "the drawing", "name a DXF file", max_bytes);
    } catch (const InputError& e) {
      throw InputError(where, name + ": " + e.message());
    }
    try {
      site::check_reading_memory(bytes, name, max_memory_, hint_);  // names the file itself
    } catch (const InputError& e) {
      throw InputError(where, e.message());
    }
    return bytes;
  }

 private:
  std::string recipe_path_;
  uint64_t max_memory_;
  std::string hint_;
};

// No files at all: the recipe is sized from its text alone.
class NoFiles : public RecipeFiles {
 public:
  std::string read(const std::string& name, const SourceLocation&, size_t) const override {
    throw FilesNeeded("the recipe reads " + name);
  }
};

// Reads the pictures of image density fields, relative to the recipe, as hostile files.
void load_density_images(Run& run) {
  for (size_t c = 0; c < run.recipe.design.curds.size(); ++c) {
    auto& density = run.recipe.design.curds[c].density;
    if (!density || density->kind != DensityKind::image) continue;
    const std::string key = "curds." + std::to_string(c) + ".density.path";
    const auto path = std::filesystem::path(run.recipe_path).parent_path() / density->path;
    LuminanceImage image = read_bounded_luminance(
        path, "the density image", SourceLocation{run.recipe_path, 0, 0, key, ""},
        run.generate.max_memory_bytes, kMaxDensityPixels, {}, kMaxDensitySide);
    // Black to white: a high-dynamic-range or broken picture is held to [0, 1] (NaN as black).
    for (float& l : image.luminance) l = l > 0 ? (l < 1 ? l : 1.0f) : 0.0f;
    density->width = image.width;
    density->height = image.height;
    density->luminance = std::make_shared<const std::vector<float>>(std::move(image.luminance));
  }
}
}  // namespace

uint64_t default_memory_limit() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || size <= 0) return uint64_t{8} << 30;
  return static_cast<uint64_t>(pages) * static_cast<uint64_t>(size) / 2;
}

uint64_t parse_bytes(const std::string& text, const std::string& name) {
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
  // Above 2^60 bytes the conversion to uint64_t would wrap: no machine has that much.
  if (used == 0 || scale == 0 || !(value > 0) || !std::isfinite(value) ||
      value * scale > 1152921504606846976.0)
    throw InputError(parameter(name), "'" + text +
                                          "' is not a size; write a positive number with K, M, G "
                                          "or T, e.g. 8G (at most 2^60 bytes)");
  // Less than a byte would read as 0, which means "the default": a limit is at least 1 K.
  if (value * scale < 1024)
    throw InputError(parameter(name),
                     "'" + text + "' is under 1K; a limit is at least 1K, e.g. 8G");
  return static_cast<uint64_t>(value * scale);
}

bool set_names_a_file(const std::string& assignment) { return override_names_a_file(assignment); }

std::string read_recipe_file(const std::string& path) {
  return read_bounded_text(path, "the recipe",
                           "a recipe is a TOML file such as patterns/tiles.toml", kMaxRecipeBytes);
}

Run resolve_run(const RunRequest& request) {
  Run run;
  run.recipe_path = request.recipe_path;
  run.recipe_text = request.recipe_text;
  run.overrides = request.overrides;
  const RecipeFolderFiles files(request.recipe_path,
                                request.max_memory ? request.max_memory : default_memory_limit(),
                                request.memory_limit_hint);
  const NoFiles none;
  run.recipe = parse_recipe(request.recipe_text, request.recipe_path, request.overrides,
                            request.read_files ? static_cast<const RecipeFiles*>(&files) : &none);
  run.seed = run.recipe.seed;
  if (!request.seed.empty()) {
    const std::string& text = request.seed;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), run.seed);
    if (ec != std::errc() || end != text.data() + text.size())
      throw InputError(parameter("seed"), "'" + text +
                                              "' is not a seed; a seed is a whole number from 0 "
                                              "to " +
                                              std::to_string(UINT64_MAX));
  }
  run.view = run.recipe.design.field;
  if (run.recipe.window) run.view = *run.recipe.window;
  if (!request.window.empty()) {
    run.view = parse_window(request.window, run.recipe.design);
    run.window_given = true;
  }
  run.generate.max_memory_bytes = request.max_memory ? request.max_memory : default_memory_limit();
  run.generate.memory_limit_hint = request.memory_limit_hint;
  if (request.read_files) load_density_images(run);
  return run;
}

CurdField run_engine(const Run& run, int threads, const std::function<void(double)>& progress) {
  std::optional<tbb::global_control> limit;
  if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, threads);
  GenerateOptions options = run.generate;
  options.progress = progress;
  return curdle(run.recipe.design, run.seed, run.view, options);
}

void start_worker_threads(int threads) {
  // An empty task queued without waiting: the scheduler creates its workers to run it.
  if (threads != 1) tbb::this_task_arena::enqueue([] {});
}

}  // namespace curdle::app
