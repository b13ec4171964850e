// Tests of cells_csv_reader.h.
#include "io/cells_csv_reader.h"

#include <gtest/gtest.h>

#include "export_support.h"
#include "recipe/recipe.h"

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
  // A Markov curd's column names its states, each with one number in the value's bits.
  EXPECT_NE(refusal("x,value,tone\n0,1,dark\n1,2,dark\n").find("line 3: curd 'tone' is 'dark'"),
            std::string::npos);
  EXPECT_NE(refusal("x,value,tone\n0,1,dark\n1,0,mid\n").find("gives its state 0, dead"),
            std::string::npos);
  EXPECT_NE(refusal("x,value,tone\n0,1,dark\n1,0,\"x\n").find("names a state"), std::string::npos);
  EXPECT_NE(refusal("x,value,a,tone\n0,3,1,dark\n1,0,dark,dead\n").find("must be 0 or 1"),
            std::string::npos);
}

TEST(CellsCsv, AMarkovCurdsStatesComeBackByNumber) {
  // A plain curd, then a chain of three living states over two planes: bits 1 and 2 of value.
  const std::string text =
      "x,value,a,tone\n0,0,0,dead\n1,3,1,dark\n2,5,1,mid\n3,4,0,mid\n4,7,1,pale\n";
  const CellsTable t = parse_cells_csv(text, 100);
  ASSERT_EQ(t.curds.size(), 2u);
  EXPECT_FALSE(t.markov(0));
  ASSERT_TRUE(t.markov(1));
  EXPECT_EQ(t.states[1], (std::vector<std::string>{"dark", "mid", "pale"}));
  EXPECT_EQ(t.state_cells[1], (std::vector<uint8_t>{0, 1, 2, 2, 3}));
  EXPECT_EQ(t.state_cells[0], (std::vector<uint8_t>{0, 1, 1, 0, 1}));
  EXPECT_EQ(t.cells[1], (std::vector<bool>{false, true, true, true, true}));
}

TEST(CellsCsv, ReadsBackAMarkovRunsFile) {
  const Design d = parse_recipe(R"(name = "m"
[lattice]
base = 2
dimension = 2
stages = 3
[[curds]]
name = "tone"
states = ["dark", "mid"]
start = "dark"
transitions = [["1", "0", "0"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]]
stages = 3
)",
                                "m.toml")
                       .design;
  const CurdField f = curdle(d, 2, d.field);
  std::ostringstream out;
  write_cells_csv(out, d, f, d.field);
  const CellsTable t = parse_cells_csv(out.str(), 1 << 20);
  ASSERT_EQ(t.curds, (std::vector<std::string>{"tone"}));
  EXPECT_EQ(t.states[0], (std::vector<std::string>{"dark", "mid"}));
  const std::vector<uint16_t> values = values_in(f, d.field);
  ASSERT_EQ(t.state_cells[0].size(), values.size());
  for (size_t i = 0; i < values.size(); ++i) EXPECT_EQ(t.state_cells[0][i], values[i]) << i;
}

}  // namespace curdle
