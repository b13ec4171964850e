// Tests of api.h without HTTP: each endpoint is a function from parameters to a JSON answer,
// and bad parameters are JSON errors that name them.
#include "server/api.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

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

}  // namespace
}  // namespace curdle::server
