// Tests of density_reader.h.
#include "recipe/density_reader.h"

#include <gtest/gtest.h>

#include "density_support.h"

namespace curdle {
TEST(Density, AnImageFieldIsReadRelativeToTheRecipe) {
  const auto dir = std::filesystem::temp_directory_path() / "curdle_density_image";
  std::filesystem::create_directories(dir);
  PreviewImage picture;
  picture.width = 8;
  picture.height = 4;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x)
      for (int ch = 0; ch < 3; ++ch) picture.rgb.push_back(x < 4 ? 0 : 255);
  std::ofstream(dir / "half.png", std::ios::binary) << encode_png(picture);
  app::RunRequest request;
  request.recipe_path = (dir / "r.toml").string();
  request.recipe_text = R"(name = "image"
[lattice]
base = 2
dimension = 2
[[curds]]
probabilities = ["1/2", "2/3"]
[curds.density]
kind = "image"
path = "half.png"
values = [0, 3]
)";
  const app::Run run = app::resolve_run(request);
  const CurdField field = app::run_engine(run, 1);
  for (int64_t y = 0; y < 4; ++y)
    for (int64_t x = 0; x < 4; ++x) EXPECT_EQ(field.value_at({x, y, 0}), x < 2 ? 0u : 1u);
  request.recipe_text.replace(request.recipe_text.find("half.png"), 8, "gone.png");
  try {
    app::resolve_run(request);
    ADD_FAILURE() << "a missing image was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("curds.0.density.path"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(Density, BadFieldsAreRefusedSayingWhatIsAllowed) {
  const std::string head = R"(name = "t"
[lattice]
base = 2
dimension = 2
mode = "MODE"
[[curds]]
probabilities = ["1/2", "1/2"]
[curds.density]
)";
  auto error_of = [&](const std::string& body, const std::string& mode = "canonical") {
    std::string text = head;
    text.replace(text.find("MODE"), 4, mode);
    try {
      parse_recipe(text + body, "r.toml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"kind = \"wave\"\n", "\"linear\", \"radial\" or \"image\""},
      {"values = [1, 2]\n", "kind"},
      {"kind = \"linear\"\nfrom = [0, 0]\nto = [0, 0]\nvalues = [1, 2]\n", "must differ"},
      {"kind = \"linear\"\nfrom = [0, 0]\nto = [4, 0]\nvalues = [1, -2]\n", "from 0 to 1000"},
      {"kind = \"linear\"\nfrom = [0, nan]\nto = [4, 0]\nvalues = [1, 2]\n", "finite"},
      {"kind = \"linear\"\nfrom = [0, 0, 0]\nto = [4, 0]\nvalues = [1, 2]\n", "[x, y] in cells"},
      {"kind = \"linear\"\nfrom = [0, 0]\nto = [4, 0]\nvalues = [1, inf]\n", "from 0 to 1000"},
      {"kind = \"radial\"\ncentre = [0, 0]\nradius = 0\nvalues = [1, 2]\n", "above 0"},
      {"kind = \"radial\"\ncentre = [0, 0]\nradius = 3\nfrom = [1, 1]\nvalues = [1, 2]\n",
       "belongs to kind \"linear\""},
      {"kind = \"image\"\nvalues = [1, 2]\n", "path"},
      {"kind = \"image\"\npath = \"a.png\"\nrect = [0, 0, 0, 4]\nvalues = [1, 2]\n",
       "sizes above 0"},
      {"kind = \"radial\"\ncentre = [0, 0]\nradius = 3\nvalues = [1, 2]\ncolour = 1\n", "colour"},
  };
  for (const auto& [body, want] : cases) {
    const std::string got = error_of(body);
    EXPECT_NE(got.find(want), std::string::npos) << body << " -> " << got;
    EXPECT_NE(got.find("curds.0.density"), std::string::npos) << body << " -> " << got;
  }
  const std::string exact =
      error_of("kind = \"radial\"\ncentre = [0, 0]\nradius = 3\nvalues = [1, 2]\n", "exact");
  EXPECT_NE(exact.find("lattice.mode = \"canonical\""), std::string::npos) << exact;
}

}  // namespace curdle
