// RFC 4180 fields: quoted only when they must be, quotes doubled, formulas shown as text.
#include "io/csv_field.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {

TEST(CsvField, QuotedOnlyWhenItHoldsACommaAQuoteOrALineBreak) {
  EXPECT_EQ(csv_field("Grès brick"), "Grès brick");
  EXPECT_EQ(csv_field(""), "");
  EXPECT_EQ(csv_field("215 x 65, red"), "\"215 x 65, red\"");
  EXPECT_EQ(csv_field("a \"b\" c"), "\"a \"\"b\"\" c\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
}

TEST(CsvField, AFormulaIsShownAsTextInsideItsQuotes) {
  EXPECT_EQ(csv_field("=SUM(A1)"), "'=SUM(A1)");
  EXPECT_EQ(csv_field("-5"), "'-5");
  EXPECT_EQ(csv_field("=1,2"), "\"'=1,2\"");
  EXPECT_EQ(csv_field("\rx"), "\"'\rx\"");
  EXPECT_EQ(csv_field("@\"x\""), "\"'@\"\"x\"\"\"");
}

TEST(CsvField, AppendedAtTheEndOfARow) {
  std::string row = "P-1,";
  append_csv_field(row, "a,b");
  row += ',';
  append_csv_field(row, "c");
  EXPECT_EQ(row, "P-1,\"a,b\",c");
}

}  // namespace
}  // namespace curdle
