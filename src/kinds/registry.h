// The one table of layout kinds: the built-in ones (tile, paving, facade, perforation, park,
// rhythm, blocks) and any a library user registers. Recipes name a kind by its name().
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "layout/layout_kind.h"

namespace curdle {

// Every kind, the built-in ones first, in the order recipes' documentation lists them.
const std::vector<const LayoutKind*>& layout_kinds();

// The kind recipes call `name` ("façade" is "facade"), or nullptr.
const LayoutKind* find_layout_kind(std::string_view name);

// The kind called `name`; asking for one that is not registered is a programming error.
const LayoutKind& layout_kind(std::string_view name);

// Adds a kind, kept for the life of the program. A name already taken is a programming error.
void register_layout_kind(std::unique_ptr<const LayoutKind> kind);

// "tile", "paving", ... quoted and joined, for messages that list what is allowed.
std::string layout_kind_names();

}  // namespace curdle
