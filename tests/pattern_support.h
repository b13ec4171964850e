// A shipped pattern laid as `curdle generate` lays it, for the tests of what is drawn from it.
#pragma once

#include <string>

#include "app/run.h"
#include "layout/builder.h"

namespace curdle::test {

// patterns/NAME resolved and laid with its own seed and view.
inline Layout pattern_layout(const std::string& name) {
  app::RunRequest request;
  request.recipe_path = std::string(CURDLE_SOURCE_DIR) + "/patterns/" + name;
  request.recipe_text = app::read_recipe_file(request.recipe_path);
  const app::Run run = app::resolve_run(request);
  const CurdField field = app::run_engine(run, 0);
  Layout layout = make_layout(run.recipe.design, field, run.view, *run.recipe.layout);
  layout.source.seed = run.seed;
  return layout;
}

}  // namespace curdle::test
