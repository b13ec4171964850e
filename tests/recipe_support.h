// A recipe with every key, and files beside a recipe in memory, which the recipe reading tests
// share.
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "curdle/error.h"
#include "layout/builder.h"
#include "recipe/recipe.h"

namespace curdle {

inline constexpr const char* kGood = R"(name = "t"
seed = 9
[lattice]
base = 4
dimension = 2
mode = "canonical"
[field]
cells = [67, 67]
[[curds]]
name = "red"
probabilities = ["3/4", "2/3"]
colour = "#c0392b"
[[curds]]
name = "blue"
probabilities = [0.75, "0.5"]
)";

inline std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parse_recipe(text, "r.toml", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// Files beside the recipe, in memory.
class FilesInMemory : public RecipeFiles {
 public:
  std::map<std::string, std::string> files;
  std::string read(const std::string& name, const SourceLocation& where, size_t) const override {
    const auto it = files.find(name);
    if (it == files.end()) throw InputError(where, name + ": no such file");
    return it->second;
  }
};

// kGood's lattice with one curd of two stages, and a [layout] of `keys`.
inline std::string with_layout(const std::string& keys) {
  return std::string(kGood).substr(0, std::string(kGood).find("[field]")) +
         "[[curds]]\nprobabilities = [\"1/2\", \"1/2\"]\n[layout]\n" + keys;
}

}  // namespace curdle
