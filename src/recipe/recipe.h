// Recipes: the TOML files in patterns/, read into a Design. Parses text, never files:
// the caller reads the file and names its source for error messages.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curdle/curd.h"
#include "layout/layout.h"
#include "recipe/recipe_files.h"

namespace curdle {

struct Recipe {
  Design design;
  uint64_t seed = 1;
  std::optional<Box> window;         // [field] window
  std::optional<LayoutSpec> layout;  // [layout]; its mask path is relative to the recipe
};

// Parses a recipe. `overrides` are "dotted.key=VALUE" (VALUE in TOML syntax, or a bare
// string), applied before validation. Files the recipe names (layout.site) are read through
// `files`; without it, a recipe naming one is refused. Throws InputError naming file, line, key
// and what is allowed.
Recipe parse_recipe(std::string_view text, const std::string& source,
                    const std::vector<std::string>& overrides = {},
                    const RecipeFiles* files = nullptr);

// The recipe's TOML with `overrides` applied (comments are not kept): what reproduces a run
// without --set. Throws InputError as parse_recipe does.
std::string recipe_text_with(std::string_view text, const std::string& source,
                             const std::vector<std::string>& overrides);

// Whether an override names a file on the machine: a key `mask`, `path` or `file` in its
// dotted key or anywhere inside the inline table or array it sets (layout={..., mask=...} sets
// layout.mask as surely as layout.mask=... does; layout.site.outline names a layer, not a
// file). Shells that serve others refuse these.
bool override_names_a_file(const std::string& assignment);

// "X,Y,W,H" (2-D), "X,W" (1-D) or "X,Y,Z,W,H,D" (3-D), checked to lie inside the field.
Box parse_window(const std::string& text, const Design& design);

// Largest sizes the engine accepts.
inline constexpr int kMaxCurds = 16;
inline constexpr int kMaxBase = 64;

}  // namespace curdle
