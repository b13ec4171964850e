// Tests of cells_csv.h.
#include "export/report/cells_csv.h"

#include <gtest/gtest.h>

#include "export_support.h"

namespace fs = std::filesystem;

namespace curdle {
using test::design;

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

}  // namespace curdle
