// A 6 x 4 m terrace of 400 x 400 mm slabs with 8 mm joints in two colours, drawn as SVG: a
// program over the installed library (curdle::curdle), with the recipe in its own text. A run
// made with the application layer carries its seed and recipe into the title block.
#include <cstdio>
#include <fstream>

#include "app/generated_run.h"
#include "curdle/error.h"

int main() {
  namespace app = curdle::app;
  const char* recipe = R"(
    name = "terrace"
    [lattice]
    base = 4
    dimension = 2
    [[curds]]
    name = "dark"
    probabilities = ["3/4", "1/2", "1/2"]
    [layout]
    kind = "paving"
    tile = [400, 400]
    joint = 8
    floor = [6000, 4000]
  )";
  try {
    const app::Run run =
        app::resolve_run({.recipe_text = recipe, .recipe_path = "terrace.toml", .seed = "11"});
    const app::GeneratedRun terrace = app::generate_run(run, true, 0, nullptr);
    std::ofstream("terrace.svg", std::ios::binary) << app::output_bytes(terrace, "layout.svg");

    const curdle::Layout& layout = *terrace.layout;
    size_t cut = 0;
    for (const auto& e : layout.elements) cut += e.cut;
    const app::LayoutSummary summary = app::summarize_layout(layout, false);
    double laid = 0;
    for (const auto& e : layout.elements) laid += e.area();
    std::printf("terrace: %llu slabs, %zu cut, %llu dark, joints %.2f m2, seed %llu\n",
                static_cast<unsigned long long>(summary.elements), cut,
                static_cast<unsigned long long>(layout.legend[1].count),
                (layout.width * layout.height - laid) / 1e6,
                static_cast<unsigned long long>(terrace.report.seed));
  } catch (const curdle::InputError& e) {
    std::fprintf(stderr, "terrace: %s\n", e.what());
    return 2;
  }
  return 0;
}
