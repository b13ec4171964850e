#include "cli/generate_command.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/outputs.h"
#include "cli/memory_reuse.h"
#include "cli/progress.h"

namespace fs = std::filesystem;

namespace curdle::cli {
namespace {

std::string first_digits(double x) { return std::to_string(x).substr(0, 5); }

void print_summary(const app::RunSummary& s, const app::Run& run, const fs::path& dir,
                   const std::vector<fs::path>& files) {
  if (s.layout) {
    const app::LayoutSummary& l = *s.layout;
    if (l.sheets)
      std::printf("sheets: %llu, each as DXF and SVG in sheets/\n",
                  static_cast<unsigned long long>(l.sheets));
    // Cells with no element: wholly in an opening or excluded zone, or beyond the outline.
    const std::string unlaid =
        l.omitted ? fmt::format("; {} cells not laid: in openings, zones or beyond the outline",
                                l.omitted)
                  : std::string();
    std::printf("layout: %llu %ss (%llu cut%s), %.0f x %.0f mm; layout.png at 1:%g, %g dpi\n",
                static_cast<unsigned long long>(l.elements), l.element_type.c_str(),
                static_cast<unsigned long long>(l.cut), unlaid.c_str(), l.width, l.height,
                l.drawing_scale, l.dpi);
    if (!l.site.empty()) std::printf("  site: %s\n", l.site.c_str());
    for (const std::string& note : l.notes) std::printf("  note: %s\n", note.c_str());
    for (size_t i = 0; i < l.violations.size() && i < 20; ++i)
      std::printf("  rule: %s\n", l.violations[i].c_str());
    if (l.violations.size() > 20)
      std::printf("  rule: ... %zu more in report.json\n", l.violations.size() - 20);
  }
  std::printf("%s, seed %llu: %llu cells\n", run.recipe.design.name.c_str(),
              static_cast<unsigned long long>(run.seed),
              static_cast<unsigned long long>(s.report.cells));
  for (const CurdReport& c : s.report.curds) {
    // The fit beside what it should be at these stages in this view, then the limit: a crop's
    // cut boxes pull the plain fit down, so the share-weighted one is shown when they do.
    auto slope = [](const std::optional<LineFit>& f) {
      return f ? first_digits(f->slope) : std::string("-");
    };
    std::string dimension = slope(c.fit) + " (expected " + slope(c.expected_fit) + ")";
    if (c.share_weighted_fit && c.fit &&
        std::fabs(c.share_weighted_fit->slope - c.fit->slope) > 1e-9)
      dimension += ", cut boxes weighted " + slope(c.share_weighted_fit) + " (expected " +
                   slope(c.expected_share_weighted_fit) + ")";
    std::printf("  curd %-12s %llu survivors (expected %.1f), box dimension %s; limit %s\n",
                c.name.c_str(), static_cast<unsigned long long>(c.stages.back().survivors),
                c.stages.back().expected, dimension.c_str(),
                c.theory_dimension ? first_digits(*c.theory_dimension).c_str() : "-");
  }
  for (const MarkovReport& m : s.report.markov) {
    // The finest stage per state beside its expectation, and the living set's dimension.
    std::string counts;
    for (const StateStageRow& row : m.stages)
      if (row.stage == run.recipe.design.lattice.stages && row.state != "dead")
        counts += (counts.empty() ? "" : ", ") + row.state + " " + std::to_string(row.count) +
                  " (expected " + fmt::format("{:.1f}", row.expected) + ")";
    const StateSet& living = m.sets.back();
    std::printf("  Markov curd %s: %s; living set box dimension %s; limit %s\n", m.name.c_str(),
                counts.c_str(), living.fit ? first_digits(living.fit->slope).c_str() : "-",
                living.theory_dimension ? first_digits(*living.theory_dimension).c_str() : "-");
  }
  std::printf("outputs in %s:\n", fs::absolute(dir).lexically_normal().c_str());
  for (const fs::path& f : files) std::printf("  %s\n", f.lexically_relative(dir).c_str());
}

}  // namespace

std::string outputs_help() {
  std::string all, defaults;
  for (const app::Output& o : app::output_registry()) {
    all += (all.empty() ? "" : ", ") + o.name;
    if (!o.by_default) defaults += (defaults.empty() ? "all but " : ", ") + o.name;
  }
  return "Which outputs: " + all + " (those of a layout need a [layout]; default: " + defaults +
         ")";
}

int run_generate(const CommonOptions& common, const std::string& out_dir,
                 const std::vector<std::string>& outputs_named) {
  app::start_worker_threads(common.threads);
  const app::Run run = app::resolve_run(run_request(common));
  TerminalObserver observer;
  const auto outputs = app::select_outputs(run, outputs_named, &observer);
  // Checked before the directory is made, so that a run over its limit leaves nothing.
  app::check_run_memory(run, outputs);
  if (app::builds_layout(run, outputs)) back_the_heap_with_huge_pages();
  const fs::path dir = out_dir.empty()
                           ? fs::path("curdle-out") / fs::path(common.recipe_path).stem()
                           : fs::path(out_dir);
  app::StagingDirectory sink(dir, app::is_output_name);
  const app::RunSummary summary = app::write_outputs(run, outputs, sink, common.threads, &observer);
  sink.commit();
  print_summary(summary, run, dir, sink.files());
  return 0;
}

int run_report(const CommonOptions& common) {
  const app::Run run = app::resolve_run(run_request(common));
  TerminalObserver observer;
  auto task = observer.begin("curdling");
  const CurdField field = app::run_engine(run, common.threads, [&](double f) { task->update(f); });
  task.reset();
  std::fputs(app::report_table(run, field).c_str(), stdout);
  return 0;
}

}  // namespace curdle::cli
