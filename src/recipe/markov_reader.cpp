#include "recipe/markov_reader.h"

#include <cmath>
#include <memory>
#include <set>

#include "curdle/markov.h"
#include "curdle/text.h"
#include "recipe/recipe.h"

namespace curdle::reading {
namespace {

// A chain's matrices are (S+1)^2 per stage and its report's theory takes K^2 (S+1)^3 steps:
// 15 living states, 4 bits of a value, keep both small. More tones are another curd's.
constexpr size_t kMostStates = 15;

constexpr const char* kMatrixForm =
    "a matrix of (S+1) x (S+1) probabilities, rows and columns \"dead\" first and then the "
    "states in order, each row summing to 1, e.g. [[\"1\", \"0\"], [\"1/4\", \"3/4\"]]";

// The row's sum minus 1, exactly where the entries are fractions: "1/4" (over), "-1/6"
// (short); empty when it is 1.
std::string row_excess(const std::vector<Probability>& row) {
  if (const auto sum = exact_sum(row, row.size())) {
    const auto [num, den] = *sum;
    if (num == den) return {};
    std::string text(num > den ? "" : "-");
    text += std::to_string(num > den ? num - den : den - num);
    if (den != 1) {
      text += '/';
      text += std::to_string(den);
    }
    return text;
  }
  double sum = 0;
  for (const Probability& p : row) sum += p.value();
  if (std::fabs(sum - 1) <= 1e-9) return {};
  char text[32];
  std::snprintf(text, sizeof text, "%+.6g", sum - 1);
  return text;
}

std::vector<Probability> read_row(const TableReader& r, const toml::node& n,
                                  const std::string& path, size_t size) {
  const toml::array* a = n.as_array();
  if (!a || a->size() != size)
    r.fail_node(n, path,
                "must be a row of " + std::to_string(size) +
                    " probabilities (dead first, then each state), not " +
                    (a ? std::to_string(a->size()) + " entries" : std::string("a single value")));
  std::vector<Probability> row;
  for (size_t j = 0; j < size; ++j)
    row.push_back(read_probability(r, *a->get(j), path + "." + std::to_string(j)));
  return row;
}

std::vector<std::vector<Probability>> read_matrix(const TableReader& r, const toml::node& n,
                                                  const std::string& path,
                                                  const std::vector<std::string>& names, int stage,
                                                  const Lattice& lattice) {
  const size_t size = names.size();
  const toml::array* a = n.as_array();
  if (!a || a->size() != size)
    r.fail_node(n, path,
                "stage " + std::to_string(stage) + "'s matrix must have " + std::to_string(size) +
                    " rows for dead and the " + std::to_string(size - 1) + " states, not " +
                    (a ? std::to_string(a->size()) : std::string("a single value")) + "; " +
                    kMatrixForm);
  std::vector<std::vector<Probability>> m;
  for (size_t i = 0; i < size; ++i) {
    const std::string row_path = path + "." + std::to_string(i);
    m.push_back(read_row(r, *a->get(i), row_path, size));
    if (const std::string excess = row_excess(m.back()); !excess.empty())
      r.fail_node(*a->get(i), row_path,
                  "row '" + names[i] + "' of stage " + std::to_string(stage) + " sums to 1 " +
                      (excess[0] == '-' ? "- " + excess.substr(1) : "+ " + excess) +
                      ", not 1: a cell's children must take some state, dead included");
    if (lattice.mode == Mode::exact)
      for (size_t j = 0; j < size; ++j)
        if (!m.back()[j].times_is_whole(lattice.children()))
          r.fail_node(*a->get(i)->as_array()->get(j), row_path + "." + std::to_string(j),
                      "exact mode splits the " + std::to_string(lattice.children()) +
                          " subcells of each cell as the row says, and " + m.back()[j].text() +
                          " * " + std::to_string(lattice.children()) +
                          " is not a whole number; use multiples of 1/" +
                          std::to_string(lattice.children()) +
                          ", or mode \"canonical\" or \"quota\"");
  }
  return m;
}

std::vector<std::string> read_states(TableReader& r) {
  const toml::node* n = r.get("states");
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a || a->empty())
    r.fail("states", "must list the living states by name, e.g. [\"dark\", \"mid\"]");
  std::vector<std::string> states;
  std::set<std::string> seen{"dead"};
  for (size_t i = 0; i < a->size(); ++i) {
    const auto s = a->get(i)->value<std::string>();
    const std::string path = r.key_path("states." + std::to_string(i));
    if (!s || !a->get(i)->is_string() || s->empty() ||
        s->find_first_of(",\"\n\r+") != std::string::npos)
      r.fail_node(*a->get(i), path,
                  "a state is a non-empty name without commas, quotes, '+' or line breaks");
    // A state's name goes where a curd's does (legends, CSV, DXF, terminals): the same rules.
    const std::string unsafe = !valid_utf8(*s)    ? "bytes that are not UTF-8"
                               : s->size() > 4096 ? std::to_string(s->size()) + " bytes"
                                                  : unsafe_text(*s);
    if (!unsafe.empty())
      r.fail_node(*a->get(i), path,
                  "a state's name is plain text of at most 4096 bytes; this one holds " + unsafe);
    if (!seen.insert(*s).second)
      r.fail_node(*a->get(i), path,
                  *s == "dead" ? "\"dead\" is implicit (state 0, the first row and column); "
                                 "name only the living states"
                               : "'" + *s + "' is named twice; each state needs its own name");
    states.push_back(*s);
  }
  return states;
}

std::vector<Probability> read_start(TableReader& r, const std::vector<std::string>& states) {
  std::vector<Probability> start(states.size() + 1, Probability::fraction(0, 1));
  const toml::node* n = r.get("start");
  const std::string allowed = "must be a state's name, e.g. \"" + states[0] +
                              "\", or one probability per living state summing to 1";
  if (!n) {
    start[1] = Probability::fraction(1, 1);
    return start;
  }
  if (const auto name = n->value<std::string>(); name && n->is_string()) {
    for (size_t i = 0; i < states.size(); ++i)
      if (states[i] == *name) {
        start[i + 1] = Probability::fraction(1, 1);
        return start;
      }
    r.fail("start", "names no state: '" + *name + "'; " + allowed);
  }
  if (!n->as_array()) r.fail("start", allowed);
  const std::vector<Probability> row = read_row(r, *n, r.key_path("start"), states.size());
  if (const std::string excess = row_excess(row); !excess.empty())
    r.fail("start", "sums to 1 " + (excess[0] == '-' ? "- " + excess.substr(1) : "+ " + excess) +
                        ", not 1; " + allowed);
  std::copy(row.begin(), row.end(), start.begin() + 1);
  return start;
}

}  // namespace

bool is_markov_curd(const toml::table& table) {
  return table.contains("states") || table.contains("transitions");
}

std::vector<std::string> markov_curd_keys() {
  return {"name", "states", "colours", "start", "transitions", "stages"};
}

std::vector<CurdSpec> read_markov_curd(TableReader& r, const std::string& name,
                                       const Lattice& lattice, int stages, int planes_left) {
  auto chain = std::make_shared<MarkovChain>();
  chain->states = read_states(r);
  const size_t S = chain->states.size();
  if (S > kMostStates)
    r.fail("states", "has " + std::to_string(S) + " states; a Markov curd takes at most " +
                         std::to_string(kMostStates) +
                         " living states (4 bits of a cell's value); give more tones another curd");
  const int planes = std::max(1, static_cast<int>(std::bit_width(S)));
  if (planes > planes_left)
    r.fail("states", std::to_string(S) + " living states take " + std::to_string(planes) +
                         " bits of a cell's value, but only " + std::to_string(planes_left) +
                         " of the " + std::to_string(kMaxCurds) +
                         " are left after the curds before it (each plain curd takes one)");
  chain->colours.resize(S);
  if (const toml::node* n = r.get("colours")) {
    const toml::array* a = n->as_array();
    if (!a || a->size() != S)
      r.fail("colours", "must give one colour \"#rrggbb\" per state (" + std::to_string(S) + ")");
    for (size_t i = 0; i < S; ++i) {
      const auto text = a->get(i)->value<std::string>();
      chain->colours[i] = text ? parse_colour(*text) : std::nullopt;
      if (!chain->colours[i])
        r.fail_node(*a->get(i), r.key_path("colours." + std::to_string(i)),
                    "must be a colour written \"#rrggbb\", e.g. \"#3b3b3b\"");
    }
  }
  chain->start = read_start(r, chain->states);

  std::vector<std::string> names{"dead"};
  names.insert(names.end(), chain->states.begin(), chain->states.end());
  const int stated = static_cast<int>(read_int(r, "stages", 0, 1, 63));
  const toml::node* tn = r.get("transitions");
  const toml::array* t = tn ? tn->as_array() : nullptr;
  if (!t || t->empty())
    r.fail("transitions", std::string("is required: one matrix per stage, each ") + kMatrixForm);
  // One matrix (its rows are arrays of numbers) or a list of them.
  const toml::array* first_row = t->get(0)->as_array();
  // One matrix, written bare or as a list of one, with `stages` counts for every stage.
  const bool bare = first_row && !first_row->empty() && !first_row->get(0)->as_array();
  const bool one_matrix = bare || (t->size() == 1 && stated > 1);
  int K = one_matrix ? (stated   ? stated
                        : stages ? stages
                                 : lattice.stages)
                     : static_cast<int>(t->size());
  if (K == 0)
    r.fail("stages", "is needed with a single matrix: the number of stages it is used for");
  if (!one_matrix && stated && stated != K)
    r.fail("stages", "is " + std::to_string(stated) + " but transitions has " + std::to_string(K) +
                         " matrices; give one per stage");
  if (K > 63) r.fail("transitions", "at most 63 stages");
  if (stages != 0 && K != stages)
    r.fail(one_matrix ? "stages" : "transitions",
           "gives " + std::to_string(K) + " stages but the curds before it have " +
               std::to_string(stages) + "; all curds share the lattice's stages");
  for (int k = 1; k <= K; ++k) {
    const std::string path =
        bare ? r.key_path("transitions")
             : r.key_path("transitions." + std::to_string(one_matrix ? 0 : k - 1));
    const toml::node& m = bare ? *tn : *t->get(one_matrix ? 0 : static_cast<size_t>(k - 1));
    if (one_matrix && k > 1)
      chain->transitions.push_back(chain->transitions.back());
    else
      chain->transitions.push_back(read_matrix(r, m, path, names, k, lattice));
  }

  // Each plane's probabilities: the living set's survival per stage (guidance only).
  std::vector<Probability> living;
  double before = 1;
  for (int k = 1; k <= K; ++k) {
    const std::vector<double> share = state_shares(*chain, k);
    const double now = 1 - share[0];
    living.push_back(
        *Probability::from_double(before > 0 ? std::clamp(now / before, 0.0, 1.0) : 0));
    before = now;
  }
  std::vector<CurdSpec> specs;
  for (int p = 0; p < planes; ++p) {
    CurdSpec spec;
    spec.name = p == 0 ? name : name + "." + std::to_string(p);
    spec.probabilities = living;
    spec.chain = chain;
    spec.plane = p;
    specs.push_back(std::move(spec));
  }
  return specs;
}

}  // namespace curdle::reading
