// Small helpers shared by the tests: designs written inline.
#pragma once

#include <string>
#include <vector>

#include "app/run.h"
#include "curdle/curd.h"
#include "kinds/blocks.h"
#include "kinds/facade.h"
#include "kinds/park.h"
#include "kinds/perforation.h"
#include "kinds/registry.h"
#include "kinds/rhythm.h"
#include "recipe/recipe.h"

namespace curdle::test {

// The recipe `text`, named `path` in messages and commands, with `overrides`, resolved into a
// run as the shells resolve theirs.
inline app::Run run_recipe(const std::string& path, const std::string& text,
                           std::vector<std::string> overrides = {}) {
  app::RunRequest request;
  request.recipe_path = path;
  request.recipe_text = text;
  request.overrides = std::move(overrides);
  return app::resolve_run(request);
}

// A [layout] of the kind called `kind` with every key at its default.
inline LayoutSpec layout_spec(const char* kind = "tile") {
  LayoutSpec spec;
  spec.set_kind(layout_kind(kind));
  return spec;
}

inline Design design(int base, int dimension, const std::vector<std::vector<std::string>>& curds,
                     Mode mode = Mode::canonical) {
  Design d;
  d.name = "test";
  d.lattice.base = base;
  d.lattice.dimension = dimension;
  d.lattice.stages = static_cast<int>(curds.at(0).size());
  d.lattice.mode = mode;
  for (size_t i = 0; i < curds.size(); ++i) {
    CurdSpec c;
    c.name = "c";  // appended, not concatenated: GCC 12 warns falsely on "c" + string
    c.name += std::to_string(i);
    for (const auto& p : curds[i]) c.probabilities.push_back(*Probability::parse(p));
    d.curds.push_back(c);
  }
  const int64_t side = static_cast<int64_t>(d.lattice.root_side());
  for (int k = 0; k < dimension; ++k) d.field.size[k] = side;
  return d;
}

// One curd with the same probability at each of n stages.
inline std::vector<std::vector<std::string>> repeat(const std::string& p, int n) {
  return {std::vector<std::string>(n, p)};
}

// How many times `what` occurs in `text` (overlapping occurrences counted).
inline size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace curdle::test
