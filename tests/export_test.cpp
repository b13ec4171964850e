// Exporters: outputs parse in real parsers and agree with the report and the curds.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "curdle/curdling.h"
#include "curdle/error.h"
#include "curdle/overlay.h"
#include "curdle/palette.h"
#include "curdle/report.h"
#include "export/atomic_file.h"
#include "export/cells_csv.h"
#include "export/cells_csv_reader.h"
#include "export/preview_png.h"
#include "export/report_json.h"
#include "export/report_table.h"
#include "test_support.h"

namespace fs = std::filesystem;

namespace curdle {
using test::design;

namespace {

fs::path temp_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("curdle-test-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    EXPECT_TRUE(!line.empty() && line.back() == '\r') << "RFC 4180 rows end in CRLF";
    line.pop_back();
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string f;
    while (std::getline(ss, f, ',')) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

}  // namespace

TEST(ReportJson, HasTheDocumentedShapeAndAddsUp) {
  Design d = design(4, 2, {{"3/4", "2/3"}, {"3/4", "2/3"}});
  d.curds[0].name = "red";
  const CurdField f = curdle(d, 7, d.field);
  const Report r = make_report(d, 7, f, d.field);
  const auto j = nlohmann::json::parse(report_to_json(r).dump());
  EXPECT_EQ(j["seed"], 7);
  EXPECT_EQ(j["lattice"]["base"], 4);
  EXPECT_EQ(j["lattice"]["mode"], "canonical");
  ASSERT_EQ(j["curds"].size(), 2u);
  const auto& stage = j["curds"][0]["stages"][0];
  EXPECT_EQ(j["curds"][0]["name"], "red");
  for (const char* key : {"stage", "probability", "survivors", "expected", "expected_sd",
                          "box_count", "local_dimension", "theory_dimension"})
    EXPECT_TRUE(stage.contains(key)) << key;
  EXPECT_DOUBLE_EQ(stage["probability"].get<double>(), 0.75);
  EXPECT_DOUBLE_EQ(stage["expected"].get<double>(), 12.0);
  EXPECT_NEAR(stage["expected_sd"].get<double>(), 1.732, 1e-3);
  EXPECT_NEAR(j["curds"][0]["box_dimension"]["theory"].get<double>(),
              2 + std::log(0.5) / std::log(4) / 2, 1e-4);
  uint64_t total = 0;
  double expected = 0;
  for (const auto& v : j["values"])
    total += v["count"].get<uint64_t>(), expected += v["expected"].get<double>();
  EXPECT_EQ(total, 256u);
  EXPECT_NEAR(expected, 256.0, 1e-6);
  EXPECT_EQ(j["values"].size(), 4u);
  const std::string table = format_report_table(r);
  EXPECT_NE(table.find("box dimension: fit"), std::string::npos);
  EXPECT_NE(table.find("red+c1"), std::string::npos);
}

TEST(CellsCsv, OneRowPerCellWithBitsThatMakeTheValue) {
  for (int E : {1, 2, 3}) {
    Design d = design(3, E, {{"2/3", "2/3"}, {"1/3", "1"}});
    d.curds[0].name = "a";
    d.curds[1].name = "b";
    const CurdField f = curdle(d, 1, d.field);
    std::ostringstream out;
    write_cells_csv(out, d, f, d.field);
    const std::string text = out.str();
    ASSERT_EQ(text.substr(0, 3), "\xEF\xBB\xBF");  // UTF-8 to spreadsheets: names stay intact
    const auto rows = parse_csv(text.substr(3));
    ASSERT_EQ(rows.size(), d.field.cells() + 1);
    const std::vector<std::string> header =
        E == 1   ? std::vector<std::string>{"x", "value", "a", "b"}
        : E == 2 ? std::vector<std::string>{"x", "y", "value", "a", "b"}
                 : std::vector<std::string>{"x", "y", "z", "value", "a", "b"};
    EXPECT_EQ(rows[0], header);
    const auto counts = value_counts(f);
    std::vector<uint64_t> seen(4, 0);
    for (size_t i = 1; i < rows.size(); ++i) {
      ASSERT_EQ(rows[i].size(), header.size()) << "ragged row " << i;
      const int value = std::stoi(rows[i][E]);
      EXPECT_EQ(value, std::stoi(rows[i][E + 1]) + 2 * std::stoi(rows[i][E + 2]));
      Coord c{0, 0, 0};
      for (int k = 0; k < E; ++k) c[k] = std::stoll(rows[i][k]);
      EXPECT_EQ(static_cast<uint32_t>(value), f.value_at(c));
      ++seen[value];
    }
    EXPECT_EQ(seen, counts);
  }
}

TEST(Preview, ShowsEachCellInItsValueColourWithYUp) {
  Design d = design(4, 2, {{"3/4", "2/3"}, {"1/2", "1/2"}});
  const CurdField f = curdle(d, 3, d.field);
  const PreviewImage img = render_preview(d, f, d.field);
  ASSERT_EQ(img.width, 512);  // 16 cells x 32 px
  ASSERT_EQ(img.height, 512);
  const auto colours = value_colours(d.curds);
  for (int64_t y : {0, 5, 15})
    for (int64_t x : {0, 7, 15}) {
      const Rgb c = colours[f.value_at({x, y, 0})];
      const size_t px = static_cast<size_t>(x * 32 + 16),
                   py = static_cast<size_t>((15 - y) * 32 + 16);
      const uint8_t* p = &img.rgb[(py * img.width + px) * 3];
      EXPECT_EQ(Rgb({p[0], p[1], p[2]}), c) << x << "," << y;
    }
}

TEST(Preview, StripsAndSheetsAndLargeFields) {
  const Design line =
      design(2, 1, std::vector<std::vector<std::string>>{std::vector<std::string>(12, "3/4")});
  const PreviewImage strip = render_preview(line, curdle(line, 1, line.field), line.field);
  EXPECT_GT(strip.width, strip.height);
  const Design cube = design(4, 3, {{"3/4", "3/4"}});
  const PreviewImage sheet = render_preview(cube, curdle(cube, 1, cube.field), cube.field);
  EXPECT_EQ(sheet.width, sheet.height);  // 16 slices in a 4 x 4 sheet
  const Design big =
      design(2, 2, std::vector<std::vector<std::string>>{std::vector<std::string>(13, "3/4")});
  const PreviewImage down = render_preview(big, curdle(big, 1, big.field), big.field);
  EXPECT_LE(down.width, 4096);  // 8192 cells averaged two to a pixel
  EXPECT_EQ(preview_memory(big, big.field), uint64_t(down.width) * down.height * 19);
}

// Encoded with zlib, read back with OpenImageIO directly: every pixel and the resolution.
TEST(Preview, EncodesAPngThatReadsBackWithItsResolution) {
  const fs::path dir = temp_dir("png");
  Design d = design(4, 2, {{"3/4", "2/3"}});
  const PreviewImage img = render_preview(d, curdle(d, 3, d.field), d.field);
  write_file(dir / "p.png", [&](std::ostream& o) { o << encode_png(img, 300); });
  auto in = OIIO::ImageInput::open((dir / "p.png").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, img.width);
  EXPECT_EQ(in->spec().nchannels, 3);
  EXPECT_NEAR(in->spec().get_float_attribute("XResolution"), 300, 1e-3);
  std::vector<uint8_t> back(img.rgb.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, back.data()));
  EXPECT_EQ(back, img.rgb);
  const LuminanceImage grey = read_luminance(dir / "p.png");
  ASSERT_EQ(grey.width, img.width);
  EXPECT_NEAR(grey.luminance[0],
              (0.2126f * img.rgb[0] + 0.7152f * img.rgb[1] + 0.0722f * img.rgb[2]) / 255, 1e-3);
  EXPECT_THROW(read_luminance(dir / "missing.png"), std::runtime_error);
  fs::remove_all(dir);
}

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

TEST(CellsCsv, ReadsBackWhatItWritesAndRefusesWhatItCannotTrust) {
  for (int E : {1, 2, 3}) {
    Design d = design(3, E, {{"2/3", "2/3"}, {"1/3", "1"}});
    d.curds[0].name = "a";
    d.curds[1].name = "b";
    const Box view = E == 1   ? Box{{2, 0, 0}, {20, 1, 1}}
                     : E == 2 ? Box{{2, 3, 0}, {7, 5, 1}}
                              : Box{{1, 0, 2}, {4, 5, 3}};
    const CurdField f = curdle(d, 4, view);
    std::ostringstream out;
    write_cells_csv(out, d, f, view);
    const CellsTable t = parse_cells_csv(out.str(), 1 << 20);
    EXPECT_EQ(t.dimension, E);
    EXPECT_EQ(t.curds, (std::vector<std::string>{"a", "b"}));
    EXPECT_TRUE(t.box == view);
    size_t i = 0;
    for (int64_t z = 0; z < view.size[2]; ++z)
      for (int64_t y = 0; y < view.size[1]; ++y)
        for (int64_t x = 0; x < view.size[0]; ++x, ++i) {
          const uint32_t v =
              f.value_at({view.origin[0] + x, view.origin[1] + y, view.origin[2] + z});
          EXPECT_EQ(t.cells[0][i], bool(v & 1));
          EXPECT_EQ(t.cells[1][i], bool(v & 2));
        }
  }
  auto refusal = [](const std::string& text) {
    try {
      parse_cells_csv(text, 1000);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal("x,y,value,a\n0,0,1,1\n0,0,1,1\n1,1,0,0\n1,0,0,0\n")
                .find("line 3: the cell is given twice"),
            std::string::npos);
  EXPECT_NE(refusal("x,y,value,a\n0,0,2,1\n").find("not the sum of its curds' bits"),
            std::string::npos);
  EXPECT_NE(refusal("x,y,value,a\n0,0,1\n").find("3 fields; the header has 4"), std::string::npos);
  EXPECT_NE(refusal("x,y,value,a\n0,0,1,1\n5000,0,1,1\n").find("at most that many"),
            std::string::npos);
  EXPECT_NE(refusal("x,y,value,a\n0,0,1,1\n2,0,1,1\n").find("every cell of the box"),
            std::string::npos);
  EXPECT_NE(refusal("value,a\n1,1\n").find("the header must be"), std::string::npos);
  EXPECT_NE(refusal("x,value,a\nnan,1,1\n").find("x must be a whole number"), std::string::npos);
}

}  // namespace curdle
