// Tests of chain_reading.h and of `fit --states`: a chain's recipe that reads back, the reading
// the cells support, a plain curd as the one-state chain, and bad requests refused by name.
#include "app/chain_reading.h"

#include <gtest/gtest.h>

#include <sstream>

#include "app/fit_run.h"
#include "curdle/curdling.h"
#include "curdle/error.h"
#include "curdle/markov.h"
#include "curdle/overlay.h"
#include "export/report/cells_csv.h"
#include "picture_support.h"
#include "recipe/recipe.h"

namespace curdle::app {
namespace {

const char* kThreeTones = R"(name = "three"
seed = 4
[lattice]
base = 2
dimension = 2
stages = 5
[field]
cells = [128, 128]
[[curds]]
name = "tone"
states = ["dark", "mid"]
start = ["1/2", "1/2"]
transitions = [["1", "0", "0"], ["1/8", "3/4", "1/8"], ["1/8", "1/8", "3/4"]]
stages = 5
)";

const char* kTwoCurds = R"(name = "two"
seed = 4
[lattice]
base = 2
dimension = 2
stages = 5
[field]
cells = [128, 128]
[[curds]]
name = "a"
probabilities = [0.8, 0.75, 0.7, 0.75, 0.8]
[[curds]]
name = "b"
probabilities = [0.7, 0.7, 0.7, 0.7, 0.7]
)";

std::string cells_csv_of(const std::string& recipe, uint64_t seed) {
  const Design d = parse_recipe(recipe, "r.toml").design;
  std::ostringstream csv;
  write_cells_csv(csv, d, curdle(d, seed, d.field), d.field);
  return csv.str();
}

FittedRecipe fit_file(const std::string& name, const std::string& text, int states,
                      bool stage_wise = false) {
  static const auto dir = test::scratch("chain-reading");
  FitRequest r;
  r.source = test::write_file(dir / name, text).string();
  r.base = 2;
  r.stages = 5;
  r.states = states;
  r.stage_wise = stage_wise;
  return run_fit(r);
}

std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST(ChainReading, AMarkovRunsCellsComeBackAsItsChainWithARecipeThatRuns) {
  const FittedRecipe f = fit_file("three.csv", cells_csv_of(kThreeTones, 4), 0);
  ASSERT_TRUE(f.chain);
  ASSERT_TRUE(f.recipe_is_chain);
  EXPECT_EQ(f.chain->states, (std::vector<std::string>{"dark", "mid"}));
  EXPECT_EQ(f.chain->supported, "chain");
  EXPECT_GT(f.chain->margin, 10);
  const auto& dark = f.chain->fit.transitions[0][1];
  EXPECT_NEAR(dark[1].value, 0.75, 2 * (dark[1].high - dark[1].low));
  // The recipe reads back (finish() checks it) and draws the chain it names.
  const Design d = parse_recipe(f.toml, "fit.toml").design;
  ASSERT_EQ(d.curds.size(), 2u);  // the chain's two bit planes
  ASSERT_TRUE(d.curds[0].chain);
  EXPECT_EQ(d.curds[0].chain->states, f.chain->states);
  EXPECT_NE(f.toml.find("# 95 %: fixed, fixed, fixed"), std::string::npos) << f.toml;
  EXPECT_NE(f.toml.find("(supported)"), std::string::npos);
}

TEST(ChainReading, OverlaidCurdsAreSupportedAsAnOverlayAndAChainAsAChain) {
  for (const uint64_t seed : {1u, 2u, 3u}) {
    const FittedRecipe overlay = fit_file("two.csv", cells_csv_of(kTwoCurds, seed), 0);
    ASSERT_TRUE(overlay.chain);
    EXPECT_FALSE(overlay.recipe_is_chain);
    EXPECT_EQ(overlay.chain->supported, "overlay") << seed;
    for (const std::string& w : overlay.warnings)
      EXPECT_EQ(w.find("better read as"), std::string::npos) << w;
    // The same cells as a chain of their values: fitted as asked, the overlay still supported.
    const FittedRecipe asked = fit_file("two.csv", cells_csv_of(kTwoCurds, seed), 3);
    EXPECT_TRUE(asked.recipe_is_chain);
    EXPECT_EQ(asked.chain->supported, "overlay") << seed;
  }
  // The chain's values read as two curds: the chain supported, and the curds told so.
  std::string plain = cells_csv_of(kThreeTones, 5);
  // Its value column as two plain curds' bits: state 1 = curd a, state 2 = curd b.
  std::istringstream in(plain);
  std::string line, csv = "x,y,value,a,b\n";
  std::getline(in, line);
  while (std::getline(in, line)) {
    const auto v = line.substr(0, line.rfind(','));
    const int value = std::stoi(v.substr(v.rfind(',') + 1));
    csv += v + "," + std::to_string(value & 1) + "," + std::to_string(value >> 1 & 1) + "\n";
  }
  const FittedRecipe read = fit_file("as-curds.csv", csv, 0);
  ASSERT_TRUE(read.chain);
  EXPECT_EQ(read.chain->supported, "chain");
  bool told = false;
  for (const std::string& w : read.warnings) told |= w.find("--states 2") != std::string::npos;
  EXPECT_TRUE(told);
}

TEST(ChainReading, APlainCurdIsTheOneStateChain) {
  const Design d = parse_recipe(R"(name = "one"
[lattice]
base = 2
dimension = 2
stages = 5
[field]
cells = [128, 128]
[[curds]]
name = "c"
probabilities = [0.9, 0.8, 0.7, 0.8, 0.7]
)",
                                "one.toml")
                       .design;
  std::ostringstream csv;
  write_cells_csv(csv, d, curdle(d, 3, d.field), d.field);
  const FittedRecipe chain = fit_file("one.csv", csv.str(), 1);
  const FittedRecipe curd = fit_file("one.csv", csv.str(), 0);
  ASSERT_TRUE(chain.recipe_is_chain);
  EXPECT_EQ(chain.chain->readings.size(), 1u);  // the overlay of one curd is the same model
  EXPECT_TRUE(chain.chain->options.stage_wise);
  // Written as a plain curd, its probabilities near the curd fit's (the same model, fitted by
  // the full likelihood instead of stage by stage).
  const Design back = parse_recipe(chain.toml, "c.toml").design;
  ASSERT_FALSE(back.curds[0].chain);
  ASSERT_EQ(back.curds[0].probabilities.size(), 5u);
  for (size_t k = 0; k < 5; ++k) {
    const StageFit& s = curd.curds[0].fit.stages[k];
    EXPECT_NEAR(back.curds[0].probabilities[k].value(), s.probability, (s.high - s.low) / 2) << k;
  }
}

TEST(ChainReading, RowsAreWrittenToSumToOneExactly) {
  ChainReading c;
  c.curd = "t";
  c.states = {"a", "b"};
  c.colours = {"", ""};
  c.fit.start = {{0, 0, 0, true}, {1.0 / 3, 0.1, 0.5}, {2.0 / 3, 0.5, 0.9}};
  c.fit.transitions = {{{{1, 1, 1, true}, {0, 0, 0, true}, {0, 0, 0, true}},
                        {{1.0 / 3, 0, 1}, {1.0 / 3, 0, 1}, {1.0 / 3, 0, 1}},
                        {{0.12345, 0, 1}, {0.45678, 0, 1}, {0.41977, 0, 1}}}};
  const std::string toml = chain_recipe_toml(c, 4);
  EXPECT_NE(toml.find(R"(["0.3334", "0.3333", "0.3333"])"), std::string::npos) << toml;
  EXPECT_NE(toml.find(R"(["0.1234", "0.4568", "0.4198"])"), std::string::npos) << toml;
  EXPECT_NE(toml.find(R"(start = ["0.3333", "0.6667"])"), std::string::npos) << toml;
  EXPECT_NE(toml.find("stages = 4"), std::string::npos);
}

TEST(ChainReading, BadRequestsAreRefusedByName) {
  const auto dir = test::scratch("chain-reading-bad");
  const std::string two_tones =
      test::write_file(
          dir / "two.png",
          test::grey_png(64, 64, [](int x, int y) { return (x * 7 + y * 3) % 5 ? 255 : 0; }))
          .string();
  FitRequest r;
  r.source = two_tones;
  r.stages = 6;
  r.states = 2;
  EXPECT_NE(refusal([&] { run_fit(r); }).find("has 2 tones where --states 2 needs 3"),
            std::string::npos);
  r.states = 0, r.stage_wise = true;
  EXPECT_NE(refusal([&] { run_fit(r); }).find("give --states S with them"), std::string::npos);
  r.stage_wise = false, r.states = 16;
  EXPECT_NE(refusal([&] { check_fit_options(r); }).find("from 1 to 15 living states"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              fit_file("mixed.csv", "x,value,a,tone\n0,0,0,dead\n1,3,1,dark\n", 0);
            }).find("one Markov curd, or of plain curds only"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              fit_file("values.csv", cells_csv_of(kTwoCurds, 1), 2);
            }).find("has values up to 3"),
            std::string::npos);
  ChainRequest big;
  big.lattice = Lattice{2, 2, 6, Mode::canonical};
  big.view = Box{{0, 0, 0}, {64, 64, 1}};
  big.tones.assign(64 * 64, 1);
  big.max_memory = 1000;
  try {
    read_as_chain(big);
    ADD_FAILURE() << "a chain past its memory was fitted";
  } catch (const ResourceLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("over the limit of"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace curdle::app
