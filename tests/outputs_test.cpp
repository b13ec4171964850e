// The application's registry of outputs: selection, size guards, memory estimates, and the
// same bytes whichever sink they are written to.
#include "app/outputs.h"

#include <gtest/gtest.h>

#include "outputs_support.h"

namespace fs = std::filesystem;

namespace curdle::app {
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

TEST(Outputs, LargeFilesAreSkippedByDefaultWithANoteButWrittenWhenNamed) {
  const app::Run big = run_of(kTiles, {"field.cells=[600,600]"});  // 360,000 tiles
  Notes notes;
  const auto chosen = names(select_outputs(big, {}, &notes));
  EXPECT_EQ(std::count(chosen.begin(), chosen.end(), "install.svg"), 0);
  EXPECT_EQ(std::count(chosen.begin(), chosen.end(), "schedule.csv"), 1);
  EXPECT_EQ(std::count(chosen.begin(), chosen.end(), "layout.pdf"), 0);
  EXPECT_EQ(std::count(chosen.begin(), chosen.end(), "layout.ifc"), 0);
  ASSERT_EQ(notes.notes.size(), 3u);
  EXPECT_NE(notes.notes[0].find("layout.pdf skipped: 360000 elements"), std::string::npos);
  EXPECT_NE(notes.notes[1].find("layout.ifc skipped: 360000 elements"), std::string::npos);
  EXPECT_NE(notes.notes[2].find("install.svg skipped: 360000 elements"), std::string::npos);
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

TEST(Outputs, ReportJsonDescribesTheLayoutWhateverElseIsWritten) {
  const app::Run run = run_of(kTiles);
  MemorySink alone;
  write_outputs(run, select_outputs(run, {"report.json"}, nullptr), alone, 0, nullptr);
  MemorySink all;
  write_outputs(run, select_outputs(run, {}, nullptr), all, 0, nullptr);
  EXPECT_EQ(alone.files().at("report.json"), all.files().at("report.json"));
  EXPECT_NE(alone.files().at("report.json").find("\"element_type\": \"tile\""), std::string::npos);
}

}  // namespace curdle::app
