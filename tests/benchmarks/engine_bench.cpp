// Engine benchmarks (not tests): generate + report for the three cases. Run them beside
// the numpy peer with compare_with_peer.sh, which reports the ratios.
#include <benchmark/benchmark.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "curdle/boxcount.h"
#include "curdle/curdling.h"
#include "curdle/report.h"
#include "curdle/search.h"
#include "export/schedules/schedule.h"
#include "kinds/registry.h"
#include "layout/builder.h"
#include "recipe/recipe.h"
#include "server/api.h"

namespace {

curdle::Design make(int base, int dimension, const std::vector<std::string>& p) {
  curdle::Design d;
  d.name = "bench";
  d.lattice = {base, dimension, static_cast<int>(p.size()), curdle::Mode::canonical};
  curdle::CurdSpec c;
  c.name = "curd";
  for (const auto& s : p) c.probabilities.push_back(*curdle::Probability::parse(s));
  d.curds.push_back(c);
  for (int k = 0; k < dimension; ++k) d.field.size[k] = static_cast<int64_t>(d.lattice.root_side());
  return d;
}

void generate_and_report(benchmark::State& state, const curdle::Design& d) {
  // Survivor counts vary a lot between seeds; a fixed seed keeps runs comparable.
  const uint64_t seed = 1;
  for (auto _ : state) {
    const curdle::CurdField f = curdle::curdle(d, seed, d.field);
    const curdle::Report r = curdle::make_report(d, seed, f, d.field);
    benchmark::DoNotOptimize(r.values.data());
    state.counters["survivors"] = static_cast<double>(r.curds[0].stages.back().survivors);
  }
  state.counters["cells"] = static_cast<double>(d.field.cells());
}

void BM_Plane_b2_K14_p07(benchmark::State& state) {
  generate_and_report(state, make(2, 2, std::vector<std::string>(14, "0.7")));
}
BENCHMARK(BM_Plane_b2_K14_p07)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Cube_b4_K5_p08(benchmark::State& state) {
  generate_and_report(state, make(4, 3, std::vector<std::string>(5, "0.8")));
}
BENCHMARK(BM_Cube_b4_K5_p08)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

// A radial density field (curds.density) on a 4096 x 4096 plane (b = 2, K = 12, p = 0.7): each
// child of a survivor is drawn against its own threshold, and the report walks every cell for
// the field's exact expectations. Beside the same plane without a field, engine alone and with
// the report.
curdle::Design radial_plane(bool dense) {
  curdle::Design d = make(2, 2, std::vector<std::string>(12, "0.7"));
  if (dense) {
    curdle::DensityField f;
    f.kind = curdle::DensityKind::radial;
    f.centre = {2048, 2048, 0};
    f.radius = 2048;
    f.values = {3, 0.2};
    d.curds[0].density = f;
  }
  return d;
}
void BM_Density_Engine_4096(benchmark::State& state) {
  const curdle::Design d = radial_plane(state.range(0) != 0);
  for (auto _ : state) {
    const curdle::CurdField f = curdle::curdle(d, 1, d.field);
    benchmark::DoNotOptimize(f.curds.data());
  }
}
BENCHMARK(BM_Density_Engine_4096)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
void BM_Density_Report_4096(benchmark::State& state) {
  generate_and_report(state, radial_plane(state.range(0) != 0));
}
BENCHMARK(BM_Density_Report_4096)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// A Markov curd of three states (dark, mid and dead) on a 4096 x 4096 plane (b = 2, K = 12),
// each living cell keeping 3/4 of its children alive, beside the overlay of two plain curds of
// p = 3/4 on the same plane: one chain's two bit planes against two curds' (engine alone).
curdle::Design markov_plane(bool markov) {
  std::string text = "name = \"bench\"\n[lattice]\nbase = 2\ndimension = 2\nstages = 12\n";
  if (markov) {
    text +=
        "[[curds]]\nname = \"tone\"\nstates = [\"dark\", \"mid\"]\nstart = \"dark\"\n"
        "stages = 12\ntransitions = [[\"1\", \"0\", \"0\"], [\"1/4\", \"1/2\", \"1/4\"], "
        "[\"1/4\", \"1/4\", \"1/2\"]]\n";
  } else {
    std::string p;
    for (int k = 0; k < 12; ++k) p += k ? ", \"3/4\"" : "\"3/4\"";
    for (const char* name : {"a", "b"})
      text += std::string("[[curds]]\nname = \"") + name + "\"\nprobabilities = [" + p + "]\n";
  }
  return curdle::parse_recipe(text, "bench.toml").design;
}
void BM_Markov_Engine_4096(benchmark::State& state) {
  const curdle::Design d = markov_plane(state.range(0) != 0);
  for (auto _ : state) {
    const curdle::CurdField f = curdle::curdle(d, 1, d.field);
    benchmark::DoNotOptimize(f.curds.data());
  }
  state.counters["cells"] = static_cast<double>(d.field.cells());
}
BENCHMARK(BM_Markov_Engine_4096)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// Seed search as the peer does it: 64 x 64 curds (b = 4; 2/3, 1/2, 1/3), each scored by
// |survivor ratio - target| + |box dimension - target|, through search_seeds, which is what
// `curdle search` runs.
void BM_SeedSearch_64x64(benchmark::State& state) {
  const curdle::Design d = make(4, 2, {"2/3", "1/2", "1/3"});
  curdle::SearchSpec spec;
  spec.targets = {curdle::parse_target("ratio:curd=0.111", d),
                  curdle::parse_target("dimension:curd=1.5", d)};
  spec.top = 1;
  const uint64_t seeds = static_cast<uint64_t>(state.range(0));
  for (auto _ : state) {
    const auto best = curdle::search_seeds(d, d.field, spec, 0, seeds - 1);
    benchmark::DoNotOptimize(best.data());
  }
  state.counters["seeds_per_s"] =
      benchmark::Counter(static_cast<double>(seeds), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_SeedSearch_64x64)->Arg(200000)->Unit(benchmark::kMillisecond)->UseRealTime();

// Fabrication schedules of a 1000 x 1000-tile paving: schedule.csv and quantities.csv written
// to a file, streamed (the layout is built once, outside the timing).
void BM_Schedule_1M_elements(benchmark::State& state) {
  curdle::Design d = make(2, 2, std::vector<std::string>(10, "0.9"));
  d.field.size = {1000, 1000, 1};
  curdle::LayoutSpec spec;
  spec.set_kind(curdle::layout_kind("paving"));
  spec.module_w = spec.module_h = 297, spec.joint = 3;
  spec.ordering = {0.05, 20, 5000, 0};
  const curdle::Layout layout =
      curdle::make_layout(d, curdle::curdle(d, 1, d.field), d.field, spec);
  const std::string path = "/tmp/curdle-bench-schedule.csv";
  for (auto _ : state) {
    std::ofstream schedule(path, std::ios::binary), quantities(path + ".q", std::ios::binary);
    curdle::write_schedule_csv(schedule, layout);
    curdle::write_quantities_csv(quantities, layout);
  }
  state.counters["elements"] = static_cast<double>(layout.elements.size());
  std::remove(path.c_str());
  std::remove((path + ".q").c_str());
}
BENCHMARK(BM_Schedule_1M_elements)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

// The API as `curdle serve` runs it for a pattern of patterns/paper.
curdle::server::ApiContext api_context(const std::string& pattern) {
  curdle::server::ApiContext context;
  context.recipe_path = std::string(CURDLE_SOURCE_DIR) + "/patterns/paper/" + pattern + ".toml";
  std::ifstream in(context.recipe_path);
  context.recipe_text.assign(std::istreambuf_iterator<char>(in), {});
  return context;
}

// The page's regenerate: /api/generate of a 256 x 256 field (the fig. 8 pattern), with the
// cells for the canvas and the full report, as the server answers it, a new seed each time.
void BM_Serve_Generate_256x256(benchmark::State& state) {
  const curdle::server::ApiContext context = api_context("fig8-segment-of-large-curd");
  uint64_t seed = 0;
  size_t bytes = 0;
  for (auto _ : state) {
    const auto r = curdle::server::api_generate(context, {{"seed", std::to_string(++seed)}});
    if (r.status != 200) state.SkipWithError(r.body.c_str());
    bytes = r.body.size();
  }
  state.counters["response_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_Serve_Generate_256x256)->Unit(benchmark::kMillisecond)->UseRealTime();

// The page's canvas: /api/field of the fig. 8 pattern at 1024 x 1024 and 2048 x 2048 cells
// (the largest field the server draws), the curd, its report and the values as bytes, a new
// seed each time. The goal is under 20 ms at 2048 x 2048.
void BM_Serve_Field(benchmark::State& state) {
  const curdle::server::ApiContext context = api_context("fig8-segment-of-large-curd");
  const std::string side = std::to_string(state.range(0));
  uint64_t seed = 0;
  size_t bytes = 0;
  for (auto _ : state) {
    const auto r = curdle::server::api_field(
        context,
        {{"seed", std::to_string(++seed)}, {"field.cells", "[" + side + "," + side + "]"}});
    if (r.status != 200) state.SkipWithError(r.body.c_str());
    bytes = r.body.size();
  }
  state.counters["response_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_Serve_Field)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();

// The segment's own report as the page asks for it after a drag (67 x 67 cells, no cells).
void BM_Serve_Segment_67x67(benchmark::State& state) {
  const curdle::server::ApiContext context = api_context("fig8-segment-of-large-curd");
  for (auto _ : state) {
    const auto r = curdle::server::api_generate(
        context, {{"seed", "8"}, {"window", "100,40,67,67"}, {"cells", "0"}});
    if (r.status != 200) state.SkipWithError(r.body.c_str());
  }
}
BENCHMARK(BM_Serve_Segment_67x67)->Unit(benchmark::kMillisecond)->UseRealTime();

// Redrawing from the CLI's own drawing instead of the canvas: the whole 256 x 256 field of the
// two-curd tile pattern (fig. 3) laid out and written as layout.svg, 65,536 tiles.
void BM_Serve_LayoutSvg_256x256(benchmark::State& state) {
  const curdle::server::ApiContext context = api_context("fig3-two-curds");
  uint64_t seed = 0;
  size_t bytes = 0;
  for (auto _ : state) {
    const auto r = curdle::server::api_export(
        context,
        {{"seed", std::to_string(++seed)}, {"field.cells", "[256,256]"}, {"file", "layout.svg"}});
    if (r.status != 200) state.SkipWithError(r.body.c_str());
    bytes = r.body.size();
  }
  state.counters["svg_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_Serve_LayoutSvg_256x256)->Unit(benchmark::kMillisecond)->UseRealTime();

// The perforated screen's layout.glb (patterns/perforated-aluminium-screen.toml, 2,255
// openings in its fabrication sheets) as /api/export writes it: the recipe read, the curd and
// layout built and the glTF written, the same bytes as `curdle generate --outputs layout.glb`.
void BM_Screen_LayoutGlb(benchmark::State& state) {
  curdle::server::ApiContext context;
  context.recipe_path =
      std::string(CURDLE_SOURCE_DIR) + "/patterns/perforated-aluminium-screen.toml";
  std::ifstream in(context.recipe_path);
  context.recipe_text.assign(std::istreambuf_iterator<char>(in), {});
  size_t bytes = 0;
  for (auto _ : state) {
    const auto r = curdle::server::api_export(context, {{"file", "layout.glb"}});
    if (r.status != 200) state.SkipWithError(r.body.c_str());
    bytes = r.body.size();
  }
  state.counters["glb_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_Screen_LayoutGlb)->Unit(benchmark::kMillisecond)->UseRealTime();

// A site read from a surveyor's DXF and laid, recipe to schedule.csv: survey.dxf of
// patterns/sites/make_sites.py --survey (10,003 entities: a boundary of 5,000 lines and 1,000
// arcs, 20 round tree pits, 3,980 spot levels), in the folder CURDLE_SURVEY_DIR names
// (compare_with_peer.sh writes it there).
void BM_Site_Survey_10000_entities(benchmark::State& state) {
  const char* dir = std::getenv("CURDLE_SURVEY_DIR");
  if (!dir) {
    state.SkipWithError("CURDLE_SURVEY_DIR names no folder (run compare_with_peer.sh)");
    return;
  }
  curdle::server::ApiContext context;
  context.recipe_path = std::string(dir) + "/survey.toml";
  std::ifstream in(context.recipe_path);
  context.recipe_text.assign(std::istreambuf_iterator<char>(in), {});
  size_t bytes = 0;
  for (auto _ : state) {
    const auto r = curdle::server::api_export(context, {{"file", "schedule.csv"}});
    if (r.status != 200) state.SkipWithError(r.body.c_str());
    bytes = r.body.size();
  }
  state.counters["schedule_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_Site_Survey_10000_entities)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
