// The application's registry of outputs: selection, size guards, memory estimates, and the
// same bytes whichever sink they are written to.
#include "app/outputs.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "app/reproduce.h"
#include "app/zone_in_cells.h"
#include "curdle/error.h"

namespace fs = std::filesystem;

namespace curdle::app {
namespace {

const char* kTiles = R"(name = "tiles"
[lattice]
base = 2
dimension = 2
[[curds]]
name = "dark"
probabilities = ["3/4", "2/3"]
[field]
cells = [8, 8]
[layout]
kind = "tile"
tile = [300, 300]
joint = 5
)";

app::Run run_of(const std::string& text, std::vector<std::string> overrides = {}) {
  RunRequest request;
  request.recipe_text = text;
  request.recipe_path = "tiles.toml";
  request.overrides = std::move(overrides);
  return resolve_run(request);
}

std::vector<std::string> names(const std::vector<const Output*>& outputs) {
  std::vector<std::string> n;
  for (const Output* o : outputs) n.push_back(o->name);
  return n;
}

struct Notes : RunObserver {
  std::vector<std::string> notes;
  std::unique_ptr<ProgressTask> begin(const std::string&) override { return nullptr; }
  void skipped(const std::string& output, uint64_t count, const std::string& unit,
               uint64_t) override {
    notes.push_back(output + " skipped: " + std::to_string(count) + " " + unit);
  }
};

TEST(Outputs, EveryNameIsUniqueAndHasAWriter) {
  std::set<std::string> seen;
  for (const Output& o : output_registry()) {
    EXPECT_TRUE(seen.insert(o.name).second) << o.name;
    EXPECT_NE(o.write, nullptr) << o.name;
    EXPECT_FALSE(o.description.empty()) << o.name;
    EXPECT_EQ(o.skip_above == 0, o.size == nullptr) << o.name;
  }
  EXPECT_EQ(find_output("schedule"), find_output("schedule.csv"));
  EXPECT_EQ(find_output("nothing"), nullptr);
}

TEST(Outputs, DefaultsLeaveOutGltfAndNeedALayoutForLayoutFiles) {
  const app::Run with = run_of(kTiles);
  const auto all = names(select_outputs(with, {}, nullptr));
  EXPECT_EQ(std::count(all.begin(), all.end(), "layout.gltf"), 0);
  EXPECT_EQ(std::count(all.begin(), all.end(), "install.svg"), 1);
  const std::string plain = std::string(kTiles).substr(0, std::string(kTiles).find("[layout]"));
  const auto none = names(select_outputs(run_of(plain), {}, nullptr));
  EXPECT_EQ(none, (std::vector<std::string>{"report.json", "cells.csv", "preview.png"}));
  try {
    select_outputs(run_of(plain), {"install"}, nullptr);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs a [layout]"), std::string::npos) << e.what();
  }
  try {
    select_outputs(with, {"pictures"}, nullptr);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().parameter, "outputs");
    EXPECT_NE(e.message().find("allowed: report.json"), std::string::npos) << e.what();
  }
}

// Huge files nobody opens are skipped unless named: cells.csv above 10 million cells,
// schedule.csv above 2 million elements, install.svg and layout.pdf above 250,000.
TEST(Outputs, LargeFilesAreSkippedByDefaultWithANoteButWrittenWhenNamed) {
  const app::Run big = run_of(kTiles, {"field.cells=[600,600]"});  // 360,000 tiles
  Notes notes;
  const auto chosen = names(select_outputs(big, {}, &notes));
  EXPECT_EQ(std::count(chosen.begin(), chosen.end(), "install.svg"), 0);
  EXPECT_EQ(std::count(chosen.begin(), chosen.end(), "schedule.csv"), 1);
  EXPECT_EQ(std::count(chosen.begin(), chosen.end(), "layout.pdf"), 0);
  ASSERT_EQ(notes.notes.size(), 2u);
  EXPECT_NE(notes.notes[0].find("layout.pdf skipped: 360000 elements"), std::string::npos);
  EXPECT_NE(notes.notes[1].find("install.svg skipped: 360000 elements"), std::string::npos);
  EXPECT_EQ(names(select_outputs(big, {"install.svg"}, &notes)),
            std::vector<std::string>{"install.svg"});
  const app::Run huge = run_of(kTiles, {"field.cells=[1500,1500]"});
  const auto fewer = names(select_outputs(huge, {}, nullptr));
  EXPECT_EQ(std::count(fewer.begin(), fewer.end(), "schedule.csv"), 0);
}

TEST(Outputs, MemoryIsCountedPerOutputAndRefusedAsAResourceLimit) {
  app::Run run = run_of(kTiles, {"field.cells=[512,512]"});
  const auto report = select_outputs(run, {"report.json"}, nullptr);
  const auto glb = select_outputs(run, {"report.json", "layout.glb"}, nullptr);
  EXPECT_GE(estimate_run_memory(run, glb) - estimate_run_memory(run, report), 512u * 512 * 700);
  run.generate.max_memory_bytes = estimate_run_memory(run, report);
  EXPECT_NO_THROW(check_run_memory(run, report));
  EXPECT_THROW(check_run_memory(run, glb), ResourceLimitError);
}

// The page's downloads come from memory, the command line's files from a staging directory:
// the bytes are the same.
TEST(Outputs, MemoryAndDirectorySinksHoldTheSameBytes) {
  const app::Run run = run_of(kTiles);
  std::vector<const Output*> outputs;
  for (const Output& o : output_registry())
    if (o.download) outputs.push_back(&o);
  MemorySink memory;
  write_outputs(run, outputs, memory, 0, nullptr);
  const fs::path dir = fs::temp_directory_path() / "curdle-outputs-test";
  fs::remove_all(dir);
  {
    StagingDirectory staging(dir);
    write_outputs(run, outputs, staging, 0, nullptr);
    EXPECT_FALSE(fs::exists(dir / "report.json"));  // nothing until commit
    staging.commit();
  }
  for (const Output* o : outputs) {
    std::ifstream in(dir / o->name, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    ASSERT_TRUE(memory.files().count(o->name)) << o->name;
    EXPECT_EQ(bytes.str(), memory.files().at(o->name)) << o->name;
    EXPECT_FALSE(bytes.str().empty()) << o->name;
  }
  fs::remove_all(dir);
}

TEST(Outputs, ReportJsonDescribesTheLayoutWhateverElseIsWritten) {
  const app::Run run = run_of(kTiles);
  MemorySink alone;
  write_outputs(run, select_outputs(run, {"report.json"}, nullptr), alone, 0, nullptr);
  MemorySink all;
  write_outputs(run, select_outputs(run, {}, nullptr), all, 0, nullptr);
  EXPECT_EQ(alone.files().at("report.json"), all.files().at("report.json"));
  EXPECT_NE(alone.files().at("report.json").find("\"element_type\": \"tile\""), std::string::npos);
}

TEST(Outputs, TheReproducingRecipeNeedsNoOptions) {
  RunRequest request;
  request.recipe_text = kTiles;
  request.recipe_path = "tiles.toml";
  request.overrides = {"curds.0.probabilities=[\"1/2\",\"1/2\"]"};
  request.seed = "99";
  request.window = "2,2,4,4";
  const app::Run run = resolve_run(request);
  RunRequest again;
  again.recipe_text = reproducing_recipe(run);
  again.recipe_path = "again.toml";
  const app::Run back = resolve_run(again);
  EXPECT_EQ(back.seed, 99u);
  EXPECT_EQ(back.view, run.view);
  EXPECT_EQ(back.recipe.design.curds[0].probabilities[0].text(), "1/2");
  EXPECT_EQ(generate_command(run),
            "curdle generate tiles.toml --set 'curds.0.probabilities=[\"1/2\",\"1/2\"]' --seed 99 "
            "--window 2,2,4,4");
}

// Seeds run from 0 to 2^64 - 1 on the command line, the API and in recipes alike: the
// reproducing recipe of every seed reads back to it.
TEST(Outputs, TheReproducingRecipeKeepsEverySeed) {
  for (const char* seed :
       {"0", "9223372036854775807", "9223372036854775808", "18446744073709551615"}) {
    RunRequest request;
    request.recipe_text = kTiles;
    request.recipe_path = "tiles.toml";
    request.seed = seed;
    const app::Run run = resolve_run(request);
    RunRequest again;
    again.recipe_text = reproducing_recipe(run);
    again.recipe_path = "again.toml";
    EXPECT_EQ(std::to_string(resolve_run(again).seed), seed);
    RunRequest set;  // a recipe's seed set as --set seed=N or seed = "N"
    set.recipe_text = kTiles;
    set.recipe_path = "tiles.toml";
    set.overrides = {std::string("seed=") + seed};
    EXPECT_EQ(std::to_string(resolve_run(set).seed), seed);
    set.overrides = {std::string("seed=\"") + seed + "\""};
    EXPECT_EQ(std::to_string(resolve_run(set).seed), seed);
  }
  for (const char* bad :
       {"-1", "18446744073709551616", "\"-1\"", "\"+5\"", "\"\"", "\"1e3\"", "2.5", "\" 7\""}) {
    RunRequest request;
    request.recipe_text = kTiles;
    request.recipe_path = "tiles.toml";
    request.overrides = {std::string("seed=") + bad};
    EXPECT_THROW(resolve_run(request), InputError) << bad;
  }
}

TEST(Outputs, SeedsAndWindowsAreCheckedAsParameters) {
  RunRequest request;
  request.recipe_text = kTiles;
  request.recipe_path = "tiles.toml";
  request.seed = "18446744073709551616";
  try {
    resolve_run(request);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().parameter, "seed");
    EXPECT_EQ(render_error(e, [](const std::string& p) { return "--" + p; }).rfind("--seed: ", 0),
              0u);
  }
  request.seed = "";
  request.window = "1,2,3";
  try {
    resolve_run(request);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().parameter, "window");
  }
}

}  // namespace
}  // namespace curdle::app

namespace curdle::app {

// A search zone in mm becomes the cells of the elements laid in it, for any origin corner,
// and reports keep it as written.
TEST(SearchZones, MillimetresBecomeTheCellsLaidThere) {
  RunRequest request;
  request.recipe_path = std::string(CURDLE_SOURCE_DIR) + "/patterns/paper/fig7-paving-20m.toml";
  request.recipe_text = read_recipe_file(request.recipe_path);
  app::Run run = resolve_run(request);  // 300 mm tiles, no joint, from the bottom-left
  EXPECT_EQ(zone_in_cells("empty=0,0,900,600mm", run), "empty=0,0,3,2");
  EXPECT_EQ(zone_in_cells("empty:dark=1000,0,1000,300 mm", run), "empty:dark=3,0,4,1");
  EXPECT_EQ(zone_in_cells("empty=0,0,3,2", run), "empty=0,0,3,2");  // cells stay cells
  EXPECT_EQ(zone_in_cells("ratio:dark=0.1", run), "ratio:dark=0.1");
  request.overrides = {"layout.origin=\"top-right\""};
  run = resolve_run(request);  // laid from the top right: the 200 mm cut pieces are at x, y = 0
  EXPECT_EQ(zone_in_cells("empty=0,0,900,600mm", run), "empty=0,0,4,3");
  EXPECT_EQ(zone_in_cells("empty=200,200,900,600mm", run), "empty=1,1,3,2");
  for (const char* bad :
       {"empty=0,0,0,600mm", "empty=0,0,nan,600mm", "empty=0,0,600mm", "empty=30000,0,100,100mm"}) {
    try {
      zone_in_cells(bad, run);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("target"), std::string::npos) << e.what();
    }
  }
}

}  // namespace curdle::app
