// Overrides: "dotted.key=VALUE" applied to a recipe's TOML document before it is read, as
// `--set` on the command line and recipe keys in the API give them.
#pragma once

#include <toml++/toml.h>

#include <string>

namespace curdle::reading {

// Applies "a.b.0.c=VALUE" (VALUE in TOML syntax, or a bare word taken as a string) to `doc`.
// Throws InputError at the override (parameter "set") when the key cannot be set.
void apply_override(toml::table& doc, const std::string& assignment);

}  // namespace curdle::reading
