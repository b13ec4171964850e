// Tests of report_table.h: the terminal table says what report.json says, a row per stage.
#include "export/report/report_table.h"

#include <gtest/gtest.h>

#include <sstream>

#include "curdle/curdling.h"
#include "test_support.h"

namespace curdle {
namespace {

TEST(ReportTable, ARowPerStageWithTheReportsCounts) {
  const Design d = test::design(3, 2, {{"3/4", "2/3", "1/2"}});
  const Report r = make_report(d, 9, curdle(d, 9, d.field), d.field);
  const std::string table = format_report_table(r);
  EXPECT_NE(table.find("seed 9 - base 3, 2-D, 3 stages, canonical mode"), std::string::npos)
      << table;
  EXPECT_NE(table.find("curd 'c0'"), std::string::npos);
  for (const auto& stage : r.curds[0].stages) {
    // Each stage's row opens with the stage, its probability and its survivors.
    std::ostringstream row;
    row << stage.stage;
    bool found = false;
    std::istringstream lines(table);
    for (std::string line; std::getline(lines, line);) {
      std::istringstream words(line);
      std::string first, p, survivors;
      words >> first >> p >> survivors;
      found |= first == row.str() && survivors == std::to_string(stage.survivors);
    }
    EXPECT_TRUE(found) << "stage " << stage.stage << " with " << stage.survivors << "\n" << table;
  }
}

}  // namespace
}  // namespace curdle
