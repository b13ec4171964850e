// The design part of a recipe: [lattice], [[curds]] and [field], checked against the engine's
// limits (path bits, exact mode's whole counts, field sizes).
#pragma once

#include <optional>

#include "curdle/curd.h"
#include "recipe/toml_reader.h"

namespace curdle::reading {

Lattice read_lattice(TableReader& top);
// The curds; sets lattice.stages from their probabilities.
std::vector<CurdSpec> read_curds(TableReader& top, Lattice& lattice);
void check_size(TableReader& top, const Lattice& lattice);
void check_exact(TableReader& top, const Lattice& lattice, const std::vector<CurdSpec>& curds);
// The field (default: one root cell); `window` is set from field.window when given.
Box read_field(TableReader& top, const Lattice& lattice, std::optional<Box>& window);

}  // namespace curdle::reading
