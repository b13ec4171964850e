// Tests of atomic_file.h.
#include "export/atomic_file.h"

#include <gtest/gtest.h>

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
