// Markov curd recipes the Markov tests share: a recipe's text from its parts, read.
#pragma once

#include <string>

#include "recipe/recipe.h"

namespace curdle::test {

// A recipe of one Markov curd `tone` (or of the curds in `curds`, TOML [[curds]] tables).
inline Design markov_design(const std::string& lattice, const std::string& curds,
                            const std::string& field = "") {
  const std::string text = "name = \"m\"\n[lattice]\n" + lattice + "\n" +
                           (field.empty() ? "" : "[field]\n" + field + "\n") + curds;
  return parse_recipe(text, "m.toml").design;
}

// "[[curds]]" of a chain with `states`, `start` and its transitions (TOML values as text).
inline std::string markov_curd(const std::string& states, const std::string& start,
                               const std::string& transitions, const std::string& name = "tone") {
  return "[[curds]]\nname = \"" + name + "\"\nstates = " + states + "\nstart = " + start +
         "\ntransitions = " + transitions + "\n";
}

}  // namespace curdle::test
