// Tests of atomic_file.h.
#include "io/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "export_support.h"

namespace fs = std::filesystem;

namespace curdle {
using test::design;

TEST(AtomicFile, AFailedWriteLeavesNothing) {
  const fs::path dir = temp_dir("atomic");
  EXPECT_THROW(write_file(dir / "x.txt",
                          [](std::ostream& o) {
                            o << "half";
                            throw InputError("stopped halfway");
                          }),
               InputError);
  EXPECT_TRUE(fs::is_empty(dir));
  write_file(dir / "x.txt", [](std::ostream& o) { o << "whole"; });
  std::ifstream in(dir / "x.txt");
  std::string s;
  in >> s;
  EXPECT_EQ(s, "whole");
  EXPECT_THROW(write_file(dir / "missing" / "x.txt", [](std::ostream& o) { o << 1; }), InputError);
  EXPECT_THROW(make_output_dir("/proc/curdle-cannot"), InputError);
  fs::remove_all(dir);
}

}  // namespace curdle

namespace curdle {

TEST(AtomicFile, NeverReplacesADeviceOrAPipe) {
  const fs::path dir = temp_dir("atomic-special");
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(write_file(fifo, [](std::ostream& o) { o << "x"; }), InputError);
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_THROW(write_file("/dev/null", [](std::ostream& o) { o << "x"; }), InputError);
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  write_file(dir / "plain.txt", [](std::ostream& o) { o << "x"; });  // a new file is fine
  write_file(dir / "plain.txt", [](std::ostream& o) { o << "y"; });  // and so is replacing it
  fs::remove_all(dir);
}

}  // namespace curdle
