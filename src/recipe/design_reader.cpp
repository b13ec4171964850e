#include "recipe/design_reader.h"

#include <cmath>
#include <set>

#include "recipe/density_reader.h"
#include "recipe/markov_reader.h"
#include "recipe/recipe.h"

namespace curdle::reading {

Lattice read_lattice(TableReader& top) {
  const toml::table* t = read_table(top, "lattice");
  if (!t) top.fail("lattice", "is required: [lattice] with base, dimension and mode");
  TableReader r(*t, "lattice", top.source(), {"base", "dimension", "stages", "mode"});
  Lattice l;
  l.base = static_cast<int>(read_int(r, "base", 0, 2, kMaxBase, true));
  l.dimension = static_cast<int>(read_int(r, "dimension", 0, 1, 3, true));
  l.stages = static_cast<int>(read_int(r, "stages", 0, 1, 63));
  const auto mode =
      read_string(r, "mode", "\"canonical\", \"exact\" or \"quota\"").value_or("canonical");
  if (mode == "canonical")
    l.mode = Mode::canonical;
  else if (mode == "exact")
    l.mode = Mode::exact;
  else if (mode == "quota")
    l.mode = Mode::quota;
  else
    r.fail("mode", "must be \"canonical\", \"exact\" or \"quota\", not \"" + mode + "\"");
  return l;
}

std::vector<CurdSpec> read_curds(TableReader& top, Lattice& lattice) {
  const toml::node* n = top.get("curds");
  if (!n) top.fail("curds", "is required: at least one [[curds]] with name and probabilities");
  const toml::array* arr = n->as_array();
  if (!arr || !arr->is_array_of_tables())
    top.fail("curds", "must be an array of tables, written [[curds]]");
  if (arr->empty() || arr->size() > kMaxCurds)
    top.fail("curds", "must have from 1 to " + std::to_string(kMaxCurds) + " curds, not " +
                          std::to_string(arr->size()));
  std::vector<CurdSpec> curds;
  std::set<std::string> names;
  const int stated_stages = lattice.stages;  // 0 when [lattice] does not say
  int stages = 0;
  for (size_t i = 0; i < arr->size(); ++i) {
    const std::string path = "curds." + std::to_string(i);
    const toml::table& table = *arr->get(i)->as_table();
    const bool markov = is_markov_curd(table);
    TableReader r(table, path, top.source(),
                  markov ? markov_curd_keys()
                         : std::vector<std::string>{"name", "probabilities", "colour", "density"});
    CurdSpec curd;
    curd.name = read_name(r, "name").value_or("curd" + std::to_string(i));
    if (curd.name.empty() || curd.name.find_first_of(",\"\n\r+") != std::string::npos)
      r.fail("name", "must be a non-empty name without commas, quotes, '+' or line breaks");
    if (!names.insert(curd.name).second)
      r.fail("name", "'" + curd.name + "' is used by another curd; names must differ");
    if (markov) {
      std::vector<CurdSpec> planes =
          read_markov_curd(r, curd.name, lattice, stages ? stages : stated_stages,
                           kMaxCurds - static_cast<int>(curds.size()));
      stages = static_cast<int>(planes[0].probabilities.size());
      for (CurdSpec& plane : planes) curds.push_back(std::move(plane));
      continue;
    }
    const toml::node* pn = r.get("probabilities");
    if (!pn)
      r.fail("probabilities", "is required: one probability per stage, e.g. [\"3/4\", \"2/3\"]");
    const toml::array* ps = pn->as_array();
    if (!ps || ps->empty())
      r.fail("probabilities", "must be a non-empty array, one per stage, e.g. [\"3/4\", \"2/3\"]");
    for (size_t k = 0; k < ps->size(); ++k)
      curd.probabilities.push_back(
          read_probability(r, *ps->get(k), path + ".probabilities." + std::to_string(k)));
    const int K = static_cast<int>(curd.probabilities.size());
    if (K > 63) r.fail("probabilities", "at most 63 stages");
    if (stages == 0) stages = K;
    if (curds.size() >= static_cast<size_t>(kMaxCurds))
      r.fail("name", "is one curd too many: a cell's value has " + std::to_string(kMaxCurds) +
                         " bits, and the Markov curds before it take some of them");
    if (K != stages)
      r.fail("probabilities", "has " + std::to_string(K) + " stages but curd 0 has " +
                                  std::to_string(stages) +
                                  "; all curds share the lattice's stages");
    if (auto c = read_string(r, "colour", "a colour written \"#rrggbb\"")) {
      curd.colour = parse_colour(*c);
      if (!curd.colour) r.fail("colour", "must be a colour written \"#rrggbb\", e.g. \"#c0392b\"");
    }
    if (r.get("density")) curd.density = read_density(r, path, lattice, density_units(top));
    curds.push_back(std::move(curd));
  }
  if (stated_stages != 0 && stated_stages != stages)
    top.fail("curds", "the curds have " + std::to_string(stages) +
                          " probabilities each but lattice.stages is " +
                          std::to_string(stated_stages));
  lattice.stages = stages;
  return curds;
}

void check_size(TableReader& top, const Lattice& l) {
  if (l.path_bits() > kMaxPathBits + 1e-9)
    top.fail("curds", "b^(E K) = " + std::to_string(l.base) + "^(" + std::to_string(l.dimension) +
                          "*" + std::to_string(l.stages) +
                          ") cells per root is too many; at most 2^" +
                          std::to_string(kMaxPathBits) + " (fewer stages or a smaller base)");
}

void check_exact(TableReader& top, const Lattice& l, const std::vector<CurdSpec>& curds) {
  if (l.mode != Mode::exact) return;
  const uint64_t B = l.children();
  // A Markov curd's matrices were checked as they were read (markov_reader.cpp); its planes
  // follow it, so the recipe's table of curd i is found by counting the curds, not the planes.
  size_t table = 0;
  for (size_t i = 0; i < curds.size(); table += curds[i].plane == 0 ? 1 : 0, ++i) {
    if (curds[i].chain) continue;
    for (size_t k = 0; k < curds[i].probabilities.size(); ++k) {
      const Probability& p = curds[i].probabilities[k];
      if (p.times_is_whole(B)) continue;
      const std::string path =
          "curds." + std::to_string(table) + ".probabilities." + std::to_string(k);
      const auto* t = top.get("curds")->as_array()->get(table)->as_table();
      const toml::node* node = t->get("probabilities")->as_array()->get(k);
      top.fail_node(*node, path,
                    "exact mode keeps p * b^E of the " + std::to_string(B) +
                        " subcells of each survivor, and " + p.text() + " * " + std::to_string(B) +
                        " = " + std::to_string(p.value() * B) +
                        " is not a whole number; use a multiple of 1/" + std::to_string(B) +
                        ", or mode \"canonical\" or \"quota\"");
    }
  }
}

Box read_field(TableReader& top, const Lattice& l, std::optional<Box>& window) {
  Box field;
  const int64_t side = static_cast<int64_t>(l.root_side());
  for (int d = 0; d < l.dimension; ++d) field.size[d] = side;
  const toml::table* t = read_table(top, "field");
  if (!t) return field;
  TableReader r(*t, "field", top.source(), {"cells", "window"});
  const int64_t max_roots = l.dimension == 1 ? (int64_t{1} << 32) : l.dimension == 2 ? 65536 : 1024;
  // At most 2^40 cells along an axis, however large the root cells: no product overflows.
  const int64_t most = side > Box::kLimit / max_roots ? Box::kLimit : max_roots * side;
  auto read_numbers = [&](const std::string& key,
                          size_t count) -> std::optional<std::vector<int64_t>> {
    const toml::node* n = r.get(key);
    if (!n) return std::nullopt;
    const toml::array* a = n->as_array();
    std::vector<int64_t> v;
    if (a && a->size() == count)
      for (auto&& e : *a)
        if (auto x = e.value<int64_t>(); x && e.is_integer()) v.push_back(*x);
    if (v.size() != count)
      r.fail(key, "must be " + std::to_string(count) + " whole numbers for a " +
                      std::to_string(l.dimension) + "-D lattice");
    return v;
  };
  if (auto cells = read_numbers("cells", l.dimension)) {
    for (int d = 0; d < l.dimension; ++d) {
      if ((*cells)[d] < 1 || (*cells)[d] > most)
        r.fail("cells", "each size must be from 1 to " + std::to_string(most) + " cells (" +
                            std::to_string(max_roots) + " root cells of " + std::to_string(side) +
                            ", and at most 2^40)");
      field.size[d] = (*cells)[d];
    }
  }
  if (auto w = read_numbers("window", 2 * l.dimension)) {
    Box box;
    for (int d = 0; d < l.dimension; ++d) {
      box.origin[d] = (*w)[d];
      box.size[d] = (*w)[l.dimension + d];
    }
    if (!box.well_formed())
      r.fail("window", "must have origins from 0 and sizes from 1, each at most 2^40");
    window = box;  // checked against the field once the layout has sized it
  }
  return field;
}

}  // namespace curdle::reading
