#include "app/generated_run.h"

#include "outputs_support.h"

namespace curdle::app {
namespace {

// Every file a run writes through write_outputs, by name.
std::map<std::string, std::string> written(const app::Run& run) {
  MemorySink sink;
  write_outputs(run,
                select_outputs(run,
                               {"report.json", "cells.csv", "schedule.csv", "layout.svg",
                                "layout.gltf", "layout.dxf"},
                               nullptr),
                sink, 1, nullptr);
  return sink.files();
}

TEST(GeneratedRun, EachOutputsBytesAreTheFileTheCommandLineWrites) {
  const app::Run run = run_of(kTiles, {"seed=7"});
  const GeneratedRun g = generate_run(run, true, 1, nullptr);
  ASSERT_TRUE(g.layout.has_value());
  EXPECT_EQ(g.report.seed, 7u);
  for (const auto& [name, bytes] : written(run)) EXPECT_EQ(output_bytes(g, name), bytes) << name;
}

TEST(GeneratedRun, LayoutFilesNeedTheLayoutTheRunWasGeneratedWith) {
  const GeneratedRun g = generate_run(run_of(kTiles), false, 1, nullptr);
  EXPECT_FALSE(g.layout.has_value());
  EXPECT_FALSE(output_bytes(g, "cells.csv").empty());
  try {
    output_bytes(g, "layout.svg");
    FAIL() << "a layout file without the layout";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("generated without"), std::string::npos) << e.what();
  }
}

TEST(GeneratedRun, UnknownOutputsAreRefusedWithTheNamesAllowed) {
  const GeneratedRun g = generate_run(run_of(kTiles), true, 1, nullptr);
  for (const char* name : {"layout", "report.txt", "sheets", "sheets/S-R9-C9.dxf"}) {
    try {
      output_bytes(g, name);
      FAIL() << name;
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(name), std::string::npos) << m;
      EXPECT_TRUE(m.find("allowed: report.json") != std::string::npos ||
                  m.find("wrote no") != std::string::npos)
          << m;
    }
  }
}

TEST(GeneratedRun, AnotherKindsOutputIsRefusedNamingTheKind) {
  const GeneratedRun g = generate_run(run_of(kTiles), true, 1, nullptr);
  try {
    output_bytes(g, "planting.csv");
    FAIL() << "a park's schedule of tiles";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "layout.kind");
    EXPECT_NE(std::string(e.what()).find("\"park\"; this recipe's is \"tile\""), std::string::npos)
        << e.what();
  }
}

TEST(GeneratedRun, TheMemoryLimitIsCheckedBeforeCurdling) {
  app::Run run = run_of(kTiles, {"field.cells=[4096, 4096]"});
  run.generate.max_memory_bytes = 1 << 20;
  EXPECT_THROW(generate_run(run, true, 1, nullptr), ResourceLimitError);
}

}  // namespace
}  // namespace curdle::app
