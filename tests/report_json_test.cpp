// Tests of report_json.h.
#include "export/report/report_json.h"

#include <gtest/gtest.h>

#include "curdle/markov_theory.h"
#include "export/report/json_number.h"
#include "export_support.h"
#include "markov_support.h"

namespace fs = std::filesystem;

namespace curdle {
using test::design;

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

TEST(ReportJson, SmallProbabilitiesKeepTheirDigits) {
  EXPECT_EQ(probability_json(7e-89).dump(), "7e-89");
  EXPECT_EQ(probability_json(5.96e-08).dump(), "5.96e-08");
  EXPECT_EQ(probability_json(0.75).dump(), "0.75");
  EXPECT_TRUE(probability_json(std::nan("")).is_null());
  // A chain that hardly ever dies out: its extinction, about 3e-15, is written as computed.
  const Design d = test::markov_design(
      "base = 4\ndimension = 2\nstages = 3",
      test::markov_curd(R"(["alive"])", "\"alive\"", R"([[["1", "0"], ["1/8", "7/8"]]])") +
          "stages = 3\n");
  const Report r = make_report(d, 1, curdle(d, 1, d.field), d.field);
  const auto j = nlohmann::json::parse(report_to_json(r).dump());
  const double want = extinction_chance(d.lattice, *d.curds[0].chain, {false, true});
  ASSERT_GT(want, 0);
  ASSERT_LT(want, 1e-12);
  const double got = j["markov_curds"][0]["sets"][0]["extinction"].get<double>();
  EXPECT_NEAR(got, want, 1e-11 * want);
}

}  // namespace curdle
