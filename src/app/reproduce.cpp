#include "app/reproduce.h"

namespace curdle::app {
namespace {

std::string shell_quote(const std::string& word) {
  const bool plain = !word.empty() && word.find_first_not_of(
                                          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_-./,=:+@%") == std::string::npos;
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::string window_text(const Box& w, int dimension) {
  std::string text;
  for (int d = 0; d < dimension; ++d) text += std::to_string(w.origin[d]) + ",";
  for (int d = 0; d < dimension; ++d)
    text += std::to_string(w.size[d]) + (d + 1 < dimension ? "," : "");
  return text;
}

std::string generate_command(const std::string& recipe_path, const std::vector<std::string>& sets,
                             uint64_t seed, const std::optional<Box>& window, int dimension) {
  std::string command = "curdle generate ";
  command += shell_quote(recipe_path);
  for (const std::string& set : sets) {
    command += " --set ";
    command += shell_quote(set);
  }
  command += " --seed ";
  command += std::to_string(seed);
  if (window) {
    command += " --window ";
    command += window_text(*window, dimension);
  }
  return command;
}

std::string generate_command(const Run& run) {
  return generate_command(run.recipe_path, run.overrides, run.seed,
                          run.window_given ? std::optional<Box>(run.view) : std::nullopt,
                          run.recipe.design.lattice.dimension);
}

std::string reproducing_recipe(const Run& run) {
  std::vector<std::string> sets = run.overrides;
  // TOML integers stop at 2^63 - 1: larger seeds are written as text, which recipes take too.
  sets.push_back(run.seed > INT64_MAX ? "seed=\"" + std::to_string(run.seed) + "\""
                                      : "seed=" + std::to_string(run.seed));
  if (run.window_given || run.recipe.window)
    sets.push_back("field.window=[" + window_text(run.view, run.recipe.design.lattice.dimension) +
                   "]");
  return recipe_text_with(run.recipe_text, run.recipe_path, sets);
}

}  // namespace curdle::app
