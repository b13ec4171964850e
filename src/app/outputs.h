// The one list of a run's outputs: each with its name, whether it needs a [layout], whether it
// is written by default, the memory it needs, a size above which it is skipped unless named,
// and a writer to a sink. The command line, the API and the page (through /api/recipe) all
// read this list.
#pragma once

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "app/observer.h"
#include "app/output_sink.h"
#include "app/run.h"
#include "curdle/report.h"
#include "layout/installer_sheets.h"
#include "layout/layout.h"

namespace curdle::app {

// What writers read: the run, its curds and report, and its layout when it has one.
struct OutputContext {
  const Run& run;
  const CurdField& field;
  const Report& report;
  const Layout* layout;   // null without a [layout]; it holds the spec it was built from
  RunObserver* observer;  // may be null
  // The installer's sheets, planned once for install.svg, layout.pdf and layout.png, which run
  // side by side: the first to ask plans them, the others wait for that plan. (Unguarded, two
  // writers planned at once and wrote the same optional: the stacked blocks, whose labels take
  // a third of a second to place, planned them three times.)
  const InstallerPlan& installer_plan() const {
    std::call_once(plan_once_, [this] { plan_ = plan_installer_sheets(*layout); });
    return *plan_;
  }
  mutable std::optional<InstallerPlan> plan_{};
  mutable std::once_flag plan_once_{};
};

struct Output {
  std::string name;
  std::string description;
  bool needs_layout = false;
  bool by_default = true;
  bool download = true;     // one file the page can offer (not a folder, not a pair)
  bool kind_owned = false;  // written only for the kind that lists it (LayoutKind::own_outputs)
  bool for_site_drawing = false;  // written only for a surface read from a DXF ([layout.site])
  // Skipped unless named when size(run) is above this (0: never skipped): huge files nobody
  // opens are not written by accident.
  uint64_t skip_above = 0;
  const char* size_unit = "";  // what size() counts: "cells", "elements"
  uint64_t (*size)(const Run& run) = nullptr;
  // Whether this installation can write it (an optional module); null: always. A default
  // output that cannot is left out with a note, a named one is an error saying why.
  bool (*installed)(std::string* why) = nullptr;
  // Bytes needed beyond the curds and the layout while writing it.
  uint64_t (*memory)(const Run& run) = nullptr;
  void (*write)(const OutputContext& context, OutputSink& sink) = nullptr;
};

const std::vector<Output>& output_registry();
// A file or folder name a run writes (outputs, layout.bin, sheets): what a directory that is
// replaced whole may hold.
bool is_output_name(const std::string& name, bool folder);
const Output* find_output(const std::string& name);

// The outputs a run writes: those named (a name without its extension is taken too, e.g.
// "schedule"), or every default one. Named outputs that need a layout the recipe lacks are an
// InputError (parameter "outputs"), as are named outputs this installation cannot write;
// defaults too large, or not installed, are skipped with a note.
std::vector<const Output*> select_outputs(const Run& run, const std::vector<std::string>& named,
                                          RunObserver* observer);

// The kind that alone writes an output (a park's planting.csv: "park"); empty for one any
// layout writes.
std::string owner_of(const Output& o);
// Whether the output is one this run can write: its kind's, and a layout when it needs one.
bool output_applies(const Output& output, const Run& run);
// InputError naming the recipe key when it is not: [layout], or layout.kind and the kind it is
// for.
void check_output_applies(const Output& output, const Run& run);

// Bytes the run and these outputs need at once, counted before anything is allocated: the
// curds, the layout when the outputs need it (or when `with_layout` says so), and each output.
uint64_t estimate_run_memory(const Run& run, const std::vector<const Output*>& outputs);
uint64_t estimate_run_memory(const Run& run, const std::vector<const Output*>& outputs,
                             bool with_layout);
// ResourceLimitError when that is above the run's memory limit.
void check_run_memory(const Run& run, const std::vector<const Output*>& outputs);
void check_run_memory(const Run& run, const std::vector<const Output*>& outputs, bool with_layout);

// What a run made, for the caller to tell the user.
struct LayoutSummary {
  std::string element_type;
  uint64_t elements = 0, cut = 0, omitted = 0;
  uint64_t sheets = 0;           // fabrication sheets written to sheets/
  double width = 0, height = 0;  // mm
  double drawing_scale = 0;      // layout.png, 1 : scale
  double dpi = 0;
  std::string site;  // where the surface was read from (layout.site)
  std::vector<std::string> notes, violations;
};
struct RunSummary {
  Report report;
  std::optional<LayoutSummary> layout;
};

// The run's per-stage report of `field` as the terminal table `curdle report` prints.
std::string report_table(const Run& run, const CurdField& field);

// Whether the run lays out its curds: for an output drawn from the layout, and for report.json,
// which describes the layout whenever the recipe has one.
bool builds_layout(const Run& run, const std::vector<const Output*>& outputs);

// Runs the engine and writes the outputs to `sink`. Throws InputError for bad input and
// ResourceLimitError above the run's memory limit, before anything is written.
RunSummary write_outputs(const Run& run, const std::vector<const Output*>& outputs,
                         OutputSink& sink, int threads, RunObserver* observer);

}  // namespace curdle::app
