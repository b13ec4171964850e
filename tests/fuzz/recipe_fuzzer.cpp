// Fuzz target: a recipe with overrides, resolved into a run and, when it is small, laid out
// and written (report, schedule, drawings) to memory. Input: the recipe's TOML, then optionally
// a line "---" and one override (KEY=VALUE) a line. Any input may be refused with an
// InputError; none may crash, hang or allocate without bound.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/outputs.h"
#include "app/run.h"
#include "curdle/error.h"
#include "kinds/facade.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 64 * 1024) return 0;
  const std::string input(reinterpret_cast<const char*>(data), size);
  curdle::app::RunRequest request;
  request.recipe_path = "fuzz.toml";
  const size_t split = input.find("\n---\n");
  request.recipe_text = input.substr(0, split);
  if (split != std::string::npos) {
    size_t start = split + 5;
    while (start < input.size() && request.overrides.size() < 16) {
      size_t end = input.find('\n', start);
      if (end == std::string::npos) end = input.size();
      if (end > start) request.overrides.push_back(input.substr(start, end - start));
      start = end + 1;
    }
  }
  request.max_memory = uint64_t{64} << 20;
  try {
    const curdle::app::Run run = curdle::app::resolve_run(request);
    const auto& layout = run.recipe.layout;
    if (run.view.cells() > 20000 || !layout ||
        (layout->keys.find<curdle::FacadeKeys>() &&
         !layout->own<curdle::FacadeKeys>().mask.empty()))
      return 0;
    const auto outputs = curdle::app::select_outputs(
        run, {"report.json", "schedule.csv", "quantities.csv", "layout.svg", "install.svg"},
        nullptr);
    if (curdle::app::estimate_run_memory(run, outputs) > request.max_memory) return 0;
    curdle::app::MemorySink sink;
    curdle::app::write_outputs(run, outputs, sink, 1, nullptr);
  } catch (const curdle::InputError&) {
  }
  return 0;
}
