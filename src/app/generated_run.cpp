#include "app/generated_run.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <mutex>
#include <optional>

#include "curdle/error.h"
#include "curdle/stop.h"
#include "kinds/facade.h"
#include "layout/builder.h"
#include "layout/drawing_scale.h"
#include "layout/piece.h"
#include "site/mask_image.h"

namespace fs = std::filesystem;

namespace curdle::app {
namespace {

// The run's [layout] as it is laid: a façade's mask is a file beside the recipe, read here (the
// kind does no IO) and added to its openings.
LayoutSpec spec_with_mask(const Run& run) {
  LayoutSpec spec = *run.recipe.layout;
  FacadeKeys* facade = spec.keys.find<FacadeKeys>();
  if (facade && !facade->mask.empty()) {
    const fs::path mask = fs::path(run.recipe_path).parent_path() / facade->mask;
    for (const Rect& r :
         read_mask_openings(mask, (*spec.size)[0], (*spec.size)[1],
                            SourceLocation{run.recipe_path, 0, 0, "layout.mask", ""},
                            run.generate.max_memory_bytes))
      facade->openings.push_back(r);
  }
  return spec;
}

std::string single_file_outputs() {
  std::string names;
  for (const Output& o : output_registry())
    if (o.name != "sheets") names += (names.empty() ? "" : ", ") + o.name;
  return names + ", layout.bin, sheets/<sheet>.dxf or .svg";
}

// The caller's observer, told one thing at a time: the outputs are written side by side.
class SharedObserver : public RunObserver {
 public:
  explicit SharedObserver(RunObserver* to) : to_(to) {}
  std::unique_ptr<ProgressTask> begin(const std::string& what) override {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::make_unique<Task>(to_->begin(what), mutex_);
  }
  void skipped(const std::string& output, uint64_t count, const std::string& unit,
               uint64_t limit) override {
    std::lock_guard<std::mutex> lock(mutex_);
    to_->skipped(output, count, unit, limit);
  }
  void not_installed(const std::string& output, const std::string& why) override {
    std::lock_guard<std::mutex> lock(mutex_);
    to_->not_installed(output, why);
  }

 private:
  class Task : public ProgressTask {
   public:
    Task(std::unique_ptr<ProgressTask> task, std::mutex& mutex)
        : task_(std::move(task)), mutex_(mutex) {}
    ~Task() override {
      std::lock_guard<std::mutex> lock(mutex_);
      task_.reset();
    }
    void update(double fraction) override {
      std::lock_guard<std::mutex> lock(mutex_);
      if (task_) task_->update(fraction);
    }

   private:
    std::unique_ptr<ProgressTask> task_;
    std::mutex& mutex_;
  };
  RunObserver* to_;
  std::mutex mutex_;
};

}  // namespace

GeneratedRun generate_run(Run run, bool with_layout, int threads, RunObserver* observer) {
  with_layout = with_layout && run.recipe.layout.has_value();
  check_run_memory(run, {}, with_layout);
  std::optional<LayoutSpec> spec;
  if (with_layout) spec = spec_with_mask(run);
  GeneratedRun g{.run = std::move(run)};
  {
    std::unique_ptr<ProgressTask> task = observer ? observer->begin("curdling") : nullptr;
    g.field = run_engine(g.run, threads, [&](double f) {
      if (task) task->update(f);
    });
  }
  const Design& d = g.run.recipe.design;
  g.report = make_report(d, g.run.seed, g.field, g.run.view);
  // Laying cuts pieces along a site's edges on as many threads as the run may use.
  if (spec)
    tbb::task_arena(threads > 0 ? threads : tbb::task_arena::automatic).execute([&] {
      g.layout = make_layout(d, g.field, g.run.view, *spec);
    });
  return g;
}

void write_generated(const GeneratedRun& g, const std::vector<const Output*>& outputs,
                     OutputSink& sink, RunObserver* observer, int threads) {
  for (const Output* o : outputs) {
    check_output_applies(*o, g.run);
    if (o->needs_layout && !g.layout)
      throw InputError(SourceLocation{g.run.recipe_path, 0, 0, "layout", ""},
                       o->name + " needs the layout, and this run was generated without it");
  }
  check_run_memory(g.run, outputs, g.layout.has_value());
  SharedObserver shared(observer);
  const OutputContext context{g.run, g.field, g.report, g.layout ? &*g.layout : nullptr,
                              observer ? &shared : nullptr};
  // The outputs read the same run and write files of their own: side by side, at most
  // `threads` at once (the memory check above counts them all together). Each task works under
  // this thread's stop rule, as the server sets one for a request.
  std::vector<const Output*> others;
  for (const Output* o : outputs)
    if (o->name != "report.json") others.push_back(o);
  // The dearest writers first, so that no long one starts last while the other threads sit
  // idle (measured on the perforated screen brief, each alone: layout.gpkg 0.18 s with GDAL's
  // loading, layout.png 0.11, layout.ifc 0.10, layout.pdf 0.08, layout.glb 0.07, sheets 0.07,
  // schedule.csv 0.06, layout.dxf 0.05, the SVGs 0.02).
  static const std::vector<std::string> dearest = {
      "layout.gpkg", "layout.png",   "layout.ifc", "layout.pdf", "layout.glb",
      "sheets",      "schedule.csv", "layout.dxf", "layout.svg", "install.svg"};
  auto rank = [&](const Output* o) {
    return std::find(dearest.begin(), dearest.end(), o->name) - dearest.begin();
  };
  std::stable_sort(others.begin(), others.end(),
                   [&](const Output* a, const Output* b) { return rank(a) < rank(b); });
  StopRule* rule = current_stop_rule();
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  std::atomic<size_t> next{0};
  arena.execute([&] {
    // Each of the arena's threads takes the next output in that order until none is left.
    tbb::parallel_for(0, arena.max_concurrency(), [&](int) {
      const StopScope scope(rule);
      for (size_t i = next++; i < others.size(); i = next++) others[i]->write(context, sink);
    });
  });
  for (const Output* o : outputs)
    if (o->name == "report.json") o->write(context, sink);
}

std::string output_bytes(const GeneratedRun& g, const std::string& name) {
  std::string writer = name;
  if (name == "layout.bin") writer = "layout.gltf";
  if (name.rfind("sheets/", 0) == 0) writer = "sheets";
  const Output* o = find_output(writer);
  if (!o || (o->name != writer && writer != "sheets"))
    throw InputError(parameter("output"),
                     "unknown output '" + name + "'; allowed: " + single_file_outputs());
  MemorySink sink;
  write_generated(g, {o}, sink, nullptr);
  const auto file = sink.files().find(name);
  if (file == sink.files().end())
    throw InputError(parameter("output"),
                     "this run wrote no '" + name + "'" +
                         (writer == "sheets" && g.layout
                              ? "; its sheets are " + std::to_string(g.layout->sheets().size())
                              : std::string()));
  return file->second;
}

LayoutSummary summarize_layout(const Layout& layout, bool with_sheets) {
  LayoutSummary s;
  s.element_type = layout.element_type;
  s.elements = layout.elements.size();
  s.cut = cut_elements(layout);
  s.omitted = layout.omitted;
  if (with_sheets) s.sheets = layout.sheets().size();
  s.width = layout.width;
  s.height = layout.height;
  s.drawing_scale = drawing_scale(layout);
  s.dpi = layout.drawing.dpi;
  s.site = layout.site;
  s.notes = layout.notes;
  s.violations = layout.violations;
  return s;
}

}  // namespace curdle::app
