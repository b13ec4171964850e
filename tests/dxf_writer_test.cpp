// Tests of dxf_writer.h: the buffered writer writes the bytes dxflib's own DL_WriterA writes,
// group for group, and a whole drawing through dxflib's calls the same file.
#include "export/dxf/dxf_writer.h"

#include <dxflib/dl_dxf.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace curdle {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every kind of group, through any DL_WriterA, then a few entities through DL_Dxf.
void write_groups(DL_WriterA& w) {
  for (const double v : {0.0, -0.0, 1.0, -2.5, 12.5, 0.1, 1e-17, 1e-7, 123456789.123456789,
                         -9.87654321e15, 1e22, 3.0000000000000004, 2999.9999999999995})
    w.dxfReal(10, v);
  for (const int v : {0, 7, -12, 2147483647}) w.dxfInt(70, v);
  for (const int v : {0, 0x1F, 255, -1}) w.dxfHex(5, v);
  w.dxfString(1, "text with spaces");
  w.dxfString(999, std::string("a string"));
  w.dxfString(100, std::string());
  DL_Dxf dxf;
  dxf.writeHeader(w);
  w.sectionEnd();
  w.sectionEntities();
  dxf.writeCircle(w, DL_CircleData(1.25, -3.5, 0, 8), DL_Attributes("0", 256, -1, "BYLAYER", 1));
  dxf.writePolyline(w, DL_PolylineData(2, 0, 0, 1), DL_Attributes("A", 3, -1, "BYLAYER", 1));
  dxf.writeVertex(w, DL_VertexData(0.1, 0.2, 0, 0.41421356237309503));
  dxf.writeVertex(w, DL_VertexData(1e3, 2e-3, 0, 0));
  dxf.writePolylineEnd(w);
  w.sectionEnd();
  w.dxfEOF();
}

TEST(BufferedDxfWriter, WritesWhatDxflibsOwnWriterWrites) {
  const auto dir = std::filesystem::temp_directory_path() / "curdle-dxf-writer-test";
  std::filesystem::create_directories(dir);
  {
    DL_WriterA theirs((dir / "theirs.dxf").c_str(), DL_Codes::AC1015);
    write_groups(theirs);
    theirs.close();
  }
  BufferedDxfWriter ours(dir / "ours.dxf");
  ASSERT_FALSE(ours.failed());
  write_groups(ours);
  ASSERT_TRUE(ours.finish());
  const std::string expected = slurp(dir / "theirs.dxf");
  EXPECT_GT(expected.size(), 500u);
  EXPECT_EQ(slurp(dir / "ours.dxf"), expected);
  // A file that cannot be made is said so, not written past.
  EXPECT_TRUE(BufferedDxfWriter(dir / "no-such-dir" / "x.dxf").failed());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curdle
