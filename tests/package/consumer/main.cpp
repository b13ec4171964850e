// consumer RECIPE SEED OUT: runs the recipe with that seed through the installed library and
// writes its layout.svg and schedule.csv into OUT, as `curdle generate` would.
#include <app/generated_run.h>
#include <app/version.h>
#include <curdle/error.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

// docs/library.md's example, line for line as the manual gives it (package_test.sh checks that
// they agree): the courtyard on a base-3 lattice, seed 11, its layout.svg.
std::string manual_example(const std::string& text) {
  namespace app = curdle::app;
  const app::Run run = app::resolve_run({.recipe_text = text,
                                         .recipe_path = "courtyard.toml",
                                         .overrides = {"lattice.base=3"},
                                         .seed = "11"});
  const app::GeneratedRun g = app::generate_run(run, true, 0, nullptr);
  const std::string svg = app::output_bytes(g, "layout.svg");  // g.report, g.layout, g.field
  return svg;
}

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: consumer RECIPE SEED OUT\n");
    return 2;
  }
  namespace app = curdle::app;
  try {
    const app::Run run = app::resolve_run(
        {.recipe_text = app::read_recipe_file(argv[1]), .recipe_path = argv[1], .seed = argv[2]});
    const app::GeneratedRun generated = app::generate_run(run, true, 0, nullptr);
    std::filesystem::create_directories(argv[3]);
    for (const char* name : {"layout.svg", "schedule.csv"}) {
      std::ofstream(std::filesystem::path(argv[3]) / name, std::ios::binary)
          << app::output_bytes(generated, name);
    }
    const std::string svg = manual_example(app::read_recipe_file(argv[1]));
    if (svg.find("<svg") == std::string::npos) {
      std::fprintf(stderr, "consumer: the manual's example wrote no SVG\n");
      return 1;
    }
    std::printf("curdle %s: %s, seed %llu, %zu elements\n", app::version(),
                run.recipe.design.name.c_str(), static_cast<unsigned long long>(run.seed),
                generated.layout->elements.size());
  } catch (const curdle::InputError& e) {
    std::fprintf(stderr, "consumer: %s\n", curdle::render_error(e).c_str());
    return 2;
  }
  return 0;
}
