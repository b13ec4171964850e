// Tests of reading_memory.h. The estimate against the readers' peaks, measured with
// /usr/bin/time over `curdle generate` (peak less the 9.4 MiB of a run on a tiny drawing), with
// each file laid as [layout.site]'s drawing:
//   190,000 tiny SVG paths (3.8 MiB)        peak 186 MiB, estimate 237 MiB (1.27x)
//   190,000 SVG polygons (5.6 MiB)          peak 190 MiB, estimate 256 MiB (1.34x)
//   199,000 DXF LINEs (5.9 MiB)             peak 180 MiB, estimate 261 MiB (1.45x)
//   199,000 DXF CIRCLEs (5.3 MiB)           peak 179 MiB, estimate 235 MiB (1.31x)
//   3,000,000 DXF comments (17.2 MiB)       peak 176 MiB, estimate 217 MiB (1.24x)
//   one LWPOLYLINE of 2,000,000 vertices    peak 321 MiB, estimate 425 MiB (1.33x)
//   a glTF whose JSON holds 10,000,000 numbers (19.1 MiB)
//                                           peak 1944 MiB, estimate 2480 MiB (1.28x)
// so that a drawing the estimate lets through stays within its limit, and one it refuses costs
// no more than its bytes.
#include "site/reading_memory.h"

#include <gtest/gtest.h>

#include <string>

#include "dxf_text.h"
#include "site/drawing.h"

namespace curdle::site {
namespace {

TEST(ReadingMemoryTest, ASmallDrawingCostsLittle) {
  const std::string dxf =
      testing::DxfText(4)
          .begin_entities_only()
          .lwpolyline("A", "1A", {{{0, 0, 0}, {9000, 0, 0}, {9000, 9000, 0}, {0, 9000, 0}}}, true)
          .text();
  EXPECT_LT(reading_memory(dxf, "site.dxf"), 16384u);
  EXPECT_NO_THROW(check_reading_memory(dxf, "site.dxf", 1 << 20, ""));
}

// Each entity, element and JSON value is counted as the reader holds it.
TEST(ReadingMemoryTest, CountsWhatEachReaderHolds) {
  std::string lines = "0\nSECTION\n2\nENTITIES\n";
  for (int i = 0; i < 1000; ++i) lines += "0\nLINE\n8\nI\n10\n0\n20\n0\n11\n1\n21\n1\n";
  lines += "0\nENDSEC\n0\nEOF\n";
  EXPECT_GE(reading_memory(lines, "a.dxf"), 1000u * (800 + 2 * 64));

  std::string svg = "<svg>";
  for (int i = 0; i < 1000; ++i) svg += "<path d=\"M0 0L1 1Z\"/>";
  svg += "</svg>";
  EXPECT_GE(reading_memory(svg, "a.SVG"), 1000u * (300 + 800));

  std::string json = "{\"asset\":{\"version\":\"2.0\"},\"extras\":[0";
  for (int i = 0; i < 100000; ++i) json += ",0";
  json += "]}";
  EXPECT_GE(reading_memory(json, "a.gltf"), 100000u * 256);
  // The same JSON in a glb's chunk, and its binary chunk counted by its bytes alone.
  std::string glb = "glTF";
  auto word = [&](uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  word(2), word(static_cast<uint32_t>(20 + json.size() + 8 + 4000));
  word(static_cast<uint32_t>(json.size())), glb += "JSON", glb += json;
  word(4000), glb += std::string("BIN\0", 4), glb += std::string(4000, '\0');
  EXPECT_GE(reading_memory(glb, "a.glb"), 100000u * 256);
  EXPECT_LT(reading_memory(glb, "a.glb"), 100000u * 256 * 2);
}

TEST(ReadingMemoryTest, RefusesAboveTheLimitNamingIt) {
  std::string json = "{\"extras\":[0";
  for (int i = 0; i < 200000; ++i) json += ",0";
  json += "]}";
  try {
    check_reading_memory(json, "model.gltf", 16 << 20, "raise the limit with --max-memory");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("model.gltf: reading this drawing of 0.4 MiB could take up to"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("above the memory limit of 16.0 MiB; raise the limit with --max-memory"),
              std::string::npos)
        << what;
  }
  EXPECT_NO_THROW(check_reading_memory(json, "model.gltf", 0, ""));  // no limit
}

}  // namespace
}  // namespace curdle::site
