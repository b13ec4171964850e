// A Markov curd in a recipe (markov.h): a [[curds]] table with `states` instead of
// `probabilities`.
//   states      = ["dark", "mid"]        the living states; "dead" is implicit and comes first
//   colours     = ["#3b3b3b", "#8c8c8c"] optional, one per state
//   start       = "dark"                 or a distribution over the living states ["1/2", "1/2"]
//   transitions = [P_1, P_2, ...]        one (S+1) x (S+1) matrix per stage, rows and columns
//                                        dead first; or one matrix with `stages = K`
//   stages      = K                      optional; with one matrix, or to check the count
#pragma once

#include <vector>

#include "curdle/curd.h"
#include "curdle/lattice.h"
#include "recipe/toml_reader.h"

namespace curdle::reading {

// Whether a [[curds]] table is a Markov curd's.
bool is_markov_curd(const toml::table& table);

// The keys a Markov curd's table may hold.
std::vector<std::string> markov_curd_keys();

// The curd's bit planes (markov.h), named after it, all sharing its chain. `stages` is the
// stage count the other curds have (0: none yet); `planes_left` how many value bits remain.
// Throws InputError naming the key and the allowed form.
std::vector<CurdSpec> read_markov_curd(TableReader& r, const std::string& name,
                                       const Lattice& lattice, int stages, int planes_left);

}  // namespace curdle::reading
