// Tests of api.h without HTTP: each endpoint is a function from parameters to a JSON answer,
// and bad parameters are JSON errors that name them.
#include "server/api.h"

#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "picture_support.h"

namespace curdle::server {
namespace {

ApiContext context() {
  ApiContext c;
  c.recipe_path = "tiles.toml";
  c.recipe_text =
      "name = \"tiles\"\n[lattice]\nbase = 2\ndimension = 2\n[[curds]]\nname = \"dark\"\n"
      "probabilities = [\"3/4\", \"2/3\"]\n[layout]\nkind = \"tile\"\n";
  return c;
}

TEST(Api, EndpointsAnswerJsonAndNameBadParameters) {
  const ApiContext c = context();
  const ApiResponse recipe = api_recipe(c);
  ASSERT_EQ(recipe.status, 200);
  const auto j = nlohmann::json::parse(recipe.body);
  EXPECT_EQ(j["name"], "tiles");
  EXPECT_EQ(j["layout"]["element"], "tile");
  const ApiResponse generated = api_generate(c, {{"seed", "4"}, {"cells", "0"}});
  ASSERT_EQ(generated.status, 200) << generated.body;
  EXPECT_FALSE(nlohmann::json::parse(generated.body).contains("values"));
  const ApiResponse bad = api_generate(c, {{"sed", "4"}});
  EXPECT_EQ(bad.status, 400);
  EXPECT_NE(bad.body.find("sed"), std::string::npos) << bad.body;
  const ApiResponse file = api_export(c, {{"file", "schedule.csv"}});
  ASSERT_EQ(file.status, 200) << file.body;
  EXPECT_EQ(file.filename, "schedule.csv");
  EXPECT_EQ(file.content_type, "text/csv; charset=utf-8");
  // A lattice too deep for 64 bits is a 400 naming stages, not a SIGFPE that ends the server.
  const ApiResponse deep = api_measure(c, {{"base", "64"}, {"stages", "30"}}, "\x89PNG");
  EXPECT_EQ(deep.status, 400) << deep.body;
  EXPECT_NE(deep.body.find("stages"), std::string::npos) << deep.body;
  // A request may not point a recipe's file at the server's disk, nor learn what is there.
  for (const char* key : {"layout.mask", "curds.0.density.path"}) {
    const ApiResponse path = api_generate(c, {{key, "\"/etc/passwd\""}});
    EXPECT_EQ(path.status, 400) << key;
    EXPECT_NE(path.body.find("names a file on the server"), std::string::npos) << path.body;
  }
  EXPECT_EQ(api_colours({{"colour", "#ff0000"}}).status, 200);
  EXPECT_EQ(api_colours({{"colour", "red"}}).status, 400);
  const auto error = nlohmann::json::parse(api_error(413, "too large").body);
  EXPECT_EQ(error["status"], 413);
  EXPECT_EQ(error["error"], "too large");
}

// /api/measure with states: the picture's tones fitted as one Markov curd, the chain and its
// recipe in the answer; a count of states the picture cannot hold is a 400 naming states.
TEST(Api, MeasureFitsAChainWhenAskedForStates) {
  const ApiContext c = context();
  // Three tones in blocks of 4 x 4 pixels: ground, and dark patches holding mid ones.
  const std::string png = test::grey_png(64, 64, [](int x, int y) -> uint8_t {
    const int bx = x / 4, by = y / 4;
    if ((bx * 7 + by * 5) % 11 < 5) return 255;
    return (bx + by) % 3 ? 60 : 140;
  });
  const ApiResponse r =
      api_measure(c, {{"base", "2"}, {"stages", "4"}, {"states", "2"}, {"name", "t.png"}}, png);
  ASSERT_EQ(r.status, 200) << r.body;
  const auto j = nlohmann::json::parse(r.body);
  EXPECT_TRUE(j["fit"]["recipe_is_chain"].get<bool>());
  EXPECT_EQ(j["fit"]["chain"]["states"].size(), 2u);
  EXPECT_EQ(j["fit"]["chain"]["transitions"][0].size(), 3u);
  EXPECT_NE(j["fit"]["recipe_toml"].get<std::string>().find("transitions = ["), std::string::npos);
  EXPECT_EQ(j["measure"]["values"].size(), 3u);
  const ApiResponse bad =
      api_measure(c, {{"base", "2"}, {"stages", "4"}, {"states", "5"}, {"name", "t.png"}}, png);
  EXPECT_EQ(bad.status, 400) << bad.body;
  EXPECT_NE(bad.body.find("--states 5 needs 6"), std::string::npos) << bad.body;
}

// /api/field: "CRD1", the head's length, the head (generate's answer without the values,
// padded to four bytes), then the values as raw bytes: the same cells generate sends in base64.
TEST(Api, FieldIsTheHeadThenTheValuesAsBytes) {
  const ApiContext c = context();
  const Params params{{"seed", "9"}, {"field.cells", "[37,21]"}};
  const ApiResponse field = api_field(c, params);
  ASSERT_EQ(field.status, 200) << field.body;
  EXPECT_EQ(field.content_type, "application/octet-stream");
  ASSERT_GE(field.body.size(), 8u);
  EXPECT_EQ(field.body.substr(0, 4), kFieldMagic);
  uint32_t n = 0;
  for (int k = 0; k < 4; ++k)
    n |= static_cast<uint32_t>(static_cast<uint8_t>(field.body[4 + k])) << (8 * k);
  EXPECT_EQ(n % 4, 0u);
  const auto head = nlohmann::json::parse(field.body.substr(8, n));
  EXPECT_FALSE(head.contains("values"));
  EXPECT_EQ(head["value_bits"], 1) << "one curd, one bit a cell";
  EXPECT_EQ(head["view"], nlohmann::json::parse("[0,0,37,21]"));
  const std::string packed = field.body.substr(8 + n);
  ASSERT_EQ(packed.size(), (37u * 21u + 7) / 8);
  std::string values;
  for (size_t i = 0; i < 37u * 21u; ++i)
    values.push_back(static_cast<char>(static_cast<uint8_t>(packed[i / 8]) >> (i % 8) & 1));
  Params with_cells = params;
  with_cells.insert({"cells", "1"});
  const auto generated = nlohmann::json::parse(api_generate(c, with_cells).body);
  EXPECT_EQ(head["report"], generated["report"]);
  // Base64 of the same bytes.
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string decoded;
  uint32_t bits = 0;
  int have = 0;
  for (const char ch : generated["values"].get<std::string>()) {
    const char* at = std::strchr(digits, ch);
    if (ch == '=' || !at) break;
    bits = bits << 6 | static_cast<uint32_t>(at - digits);
    if ((have += 6) >= 8) decoded.push_back(static_cast<char>(bits >> (have -= 8) & 0xff));
  }
  EXPECT_EQ(values, decoded);
  size_t dark = 0;
  for (const char v : values) dark += v == 1;
  EXPECT_GT(dark, 0u);
  // Bad input is a JSON error, as generate's.
  const ApiResponse bad = api_field(c, {{"seed", "x"}});
  EXPECT_EQ(bad.status, 400);
  EXPECT_NE(bad.body.find("seed"), std::string::npos) << bad.body;
}

}  // namespace
}  // namespace curdle::server
