// Fuzz target: a floor's outline and excluded zones (recipe/zone_reader.cpp) read, laid and cut
// (CGAL's exact cuts along sloping edges), and written to a schedule and layout.svg. Input: the
// outline's TOML value on the first line (empty: none), then one zone polygon's value a line,
// at most eight. Any input may be refused with an InputError; none may crash, hang or allocate
// without bound.
#include <cstddef>
#include <cstdint>
#include <string>

#include "app/outputs.h"
#include "app/run.h"
#include "curdle/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 16 * 1024) return 0;
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::string recipe =
      "[lattice]\nbase = 2\ndimension = 2\n[[curds]]\nprobabilities = [\"3/4\", \"2/3\"]\n"
      "[layout]\nkind = \"paving\"\ntile = [600, 600]\njoint = 5\nfloor = [9000, 6000]\n";
  size_t start = 0, end = input.find('\n');
  const std::string outline = input.substr(0, end);
  if (!outline.empty()) recipe += "outline = " + outline + "\n";
  for (int zone = 0; end != std::string::npos && zone < 8;) {
    start = end + 1;
    end = input.find('\n', start);
    const std::string polygon = input.substr(start, end - start);
    if (polygon.empty()) continue;
    recipe += "[[layout.zones]]\nname = \"z" + std::to_string(zone++) +
              "\"\nrule = \"exclude\"\npolygon = " + polygon + "\n";
  }
  curdle::app::RunRequest request;
  request.recipe_path = "zones.toml";
  request.recipe_text = recipe;
  request.max_memory = uint64_t{64} << 20;
  try {
    const curdle::app::Run run = curdle::app::resolve_run(request);
    const auto outputs =
        curdle::app::select_outputs(run, {"schedule.csv", "layout.svg", "layout.dxf"}, nullptr);
    curdle::app::MemorySink sink;
    curdle::app::write_outputs(run, outputs, sink, 1, nullptr);
  } catch (const curdle::InputError&) {
  }
  return 0;
}
