// Tests of bounded_file.h: a file a user names is read only when it is a regular file within
// its bound, and the error names the path and what was wanted.
#include "io/bounded_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "curdle/error.h"

namespace curdle {
namespace {

std::filesystem::path scratch_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::path(::testing::TempDir()) / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string read_refusal(const std::string& path, uint64_t max_bytes) {
  try {
    read_bounded_text(path, "the recipe", "a recipe is a TOML file", max_bytes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BoundedFile, AFileWithinItsBoundIsReadWhole) {
  const std::string text("seed = 1\n\0after a zero byte\n", 28);
  const auto path = scratch_file("bounded.toml", text);
  EXPECT_EQ(read_bounded_text(path.string(), "the recipe", "a recipe", 28), text);
  EXPECT_EQ(read_own_file(path), text);
}

TEST(BoundedFile, AFileOverItsBoundIsRefusedWithItsSize) {
  const auto path = scratch_file("big.toml", std::string(4096, 'x'));
  const std::string why = read_refusal(path.string(), 1024);
  EXPECT_NE(why.find("4096 bytes"), std::string::npos) << why;
  EXPECT_NE(why.find(path.string()), std::string::npos) << why;
}

TEST(BoundedFile, ADeviceOrADirectoryOrNothingIsRefused) {
  EXPECT_NE(
      read_refusal("/dev/zero", 1 << 20).find("is not a regular file; a recipe is a TOML file"),
      std::string::npos);
  EXPECT_NE(read_refusal(::testing::TempDir(), 1 << 20).find("is not a regular file"),
            std::string::npos);
  EXPECT_NE(read_refusal("/no/such/recipe.toml", 1 << 20).find("cannot read the recipe"),
            std::string::npos);
  EXPECT_EQ(read_own_file("/no/such/file"), "");
}

}  // namespace
}  // namespace curdle
