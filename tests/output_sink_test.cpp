// Tests of output_sink.h.
#include "app/output_sink.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>

#include "outputs_support.h"

namespace fs = std::filesystem;

namespace curdle::app {
// A run killed with SIGKILL leaves its hidden staging directory; the next run into the same
// place removes it (its process is gone), and leaves those of running processes alone.
TEST(StagingDirectory, RemovesWhatKilledRunsLeft) {
  const fs::path parent = fs::temp_directory_path() / "curdle-staging-test";
  fs::remove_all(parent);
  fs::create_directories(parent / ".out.curdle-2147483646" / "sheets");  // no such process
  fs::create_directories(parent / ".out.curdle-1");                      // init runs
  fs::create_directories(parent / ".other.curdle-2147483646");           // another output
  {
    StagingDirectory sink(parent / "out");
    sink.write("report.json", [](std::ostream& o) { o << "{}"; });
    sink.commit();
  }
  EXPECT_FALSE(fs::exists(parent / ".out.curdle-2147483646"));
  EXPECT_TRUE(fs::exists(parent / ".out.curdle-1"));
  EXPECT_TRUE(fs::exists(parent / ".other.curdle-2147483646"));
  EXPECT_TRUE(fs::exists(parent / "out" / "report.json"));
  fs::remove_all(parent);
}

TEST(Outputs, MemoryAndDirectorySinksHoldTheSameBytes) {
  const app::Run run = run_of(kTiles);
  std::vector<const Output*> outputs;
  for (const Output& o : output_registry())
    if (o.download && output_applies(o, run)) outputs.push_back(&o);  // not a park's
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

// A temporary file that cannot be made (the server and the Python module write layout.dxf and
// layout.gpkg through one) is a user's writing failure, as a folder that cannot be written is:
// an InputError saying where and what to do.
TEST(Outputs, ATemporaryFileThatCannotBeMadeSaysWhereAndWhatToDo) {
  struct Tmpdir {  // TMPDIR as the test sets it, then as it was
    std::optional<std::string> before;
    explicit Tmpdir(const char* value) {
      if (const char* b = std::getenv("TMPDIR")) before = b;
      ::setenv("TMPDIR", value, 1);
    }
    ~Tmpdir() {
      before ? (void)::setenv("TMPDIR", before->c_str(), 1) : (void)::unsetenv("TMPDIR");
    }
  };
  for (const char* folder : {"/no/such/folder", "/dev/null"}) {
    const Tmpdir tmpdir(folder);
    MemorySink memory;
    try {
      memory.write_via_file("layout.gpkg", [](const std::filesystem::path&) {});
      ADD_FAILURE() << "a temporary file was made in " << folder;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(folder), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("set TMPDIR"), std::string::npos) << e.what();
    }
  }
}

}  // namespace curdle::app
