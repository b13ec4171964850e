// Tests of cells_csv_reader.h.
#include "io/cells_csv_reader.h"

#include <gtest/gtest.h>

#include "export_support.h"

namespace fs = std::filesystem;

namespace curdle {
using test::design;

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
  // A Markov curd's column names its state: said plainly, as fit cannot take it yet.
  EXPECT_NE(refusal("x,y,value,tone\n0,0,1,dark\n").find("Markov curd's states cannot be fitted"),
            std::string::npos);
}

}  // namespace curdle
