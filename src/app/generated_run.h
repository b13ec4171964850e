// A run's curds, report and layout, made once and kept: a program or the Python module asks for
// any output's bytes, or writes a set of them, without curdling again.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/observer.h"
#include "app/output_sink.h"
#include "app/outputs.h"
#include "app/run.h"
#include "curdle/report.h"
#include "layout/layout.h"

namespace curdle::app {

struct GeneratedRun {
  Run run;
  CurdField field;
  Report report;
  std::optional<Layout> layout;  // when the recipe has a [layout] and it was asked for
};

// Curdles the run over its view and reports it; lays it out when `with_layout` and the recipe
// has a [layout] (a façade's mask is read beside the recipe). ResourceLimitError above the run's
// memory limit, before anything is allocated.
GeneratedRun generate_run(Run run, bool with_layout, int threads, RunObserver* observer);

// Writes `outputs` to the sink, at most `threads` side by side (0: as many as the cores),
// report.json last (it describes the layout the others drew). The sink and the observer are
// called from those threads: the sinks here keep what they hold under a lock.
// InputError when one needs a layout the run was generated without; ResourceLimitError when
// the outputs need more memory than the run may take.
void write_generated(const GeneratedRun& generated, const std::vector<const Output*>& outputs,
                     OutputSink& sink, RunObserver* observer, int threads = 0);

// One output's bytes, as `curdle generate` writes that file. `name` is a file of the registry
// (layout.svg, schedule.csv, layout.bin) or a fabrication sheet (sheets/S-R1-C1.dxf); InputError
// naming the outputs allowed otherwise.
std::string output_bytes(const GeneratedRun& generated, const std::string& name);

// What the layout holds, for the caller to tell the user.
LayoutSummary summarize_layout(const Layout& layout, bool with_sheets);

}  // namespace curdle::app
