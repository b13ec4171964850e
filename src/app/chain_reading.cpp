#include "app/chain_reading.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>

#include "app/run.h"
#include "app/toml_text.h"
#include "curdle/error.h"
#include "curdle/markov.h"
#include "curdle/markov_theory.h"
#include "curdle/theory.h"

namespace curdle::app {
namespace {

using json = nlohmann::ordered_json;

constexpr int kMostTones = 16;
constexpr size_t kEveryAssignmentUpTo = 3;  // living tones: at most 3! orders of 3 values

// Entries to 4 decimals, as whole ten-thousandths summing to 10000: each rounded down, then the
// largest remainders rounded up (Hamilton's method), so that the recipe's row sums to 1 exactly.
std::vector<std::string> row_texts(const std::vector<FittedEntry>& row) {
  std::vector<int64_t> units(row.size());
  std::vector<std::pair<double, size_t>> rest;
  int64_t sum = 0;
  for (size_t j = 0; j < row.size(); ++j) {
    const double exact = std::clamp(row[j].value, 0.0, 1.0) * 10000;
    units[j] = static_cast<int64_t>(std::floor(exact));
    sum += units[j];
    rest.push_back({exact - static_cast<double>(units[j]), j});
  }
  std::sort(rest.begin(), rest.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  for (size_t i = 0; sum < 10000 && i < rest.size(); ++i, ++sum) ++units[rest[i].second];
  std::vector<std::string> out;
  for (const int64_t u : units)
    out.push_back(u == 10000 ? "1" : u == 0 ? "0" : fmt::format("0.{:04d}", u));
  return out;
}

std::string quoted_list(const std::vector<std::string>& items) {
  std::string out = "[";
  for (size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + toml_quoted(items[i]);
  return out + "]";
}

std::string interval_text(const FittedEntry& e) {
  return e.fixed ? "fixed" : fmt::format("{:.4f}-{:.4f}", e.low, e.high);
}

// The overlay's values for the living tones: every injective assignment to 1..2^n - 1 for a few
// tones, the tones in order for more.
std::vector<std::vector<int>> assignments(size_t living, int curds) {
  const int values = (1 << curds) - 1;
  std::vector<std::vector<int>> out;
  if (living > kEveryAssignmentUpTo) {
    std::vector<int> order(living + 1);
    std::iota(order.begin(), order.end(), 0);
    return {order};
  }
  std::vector<int> pool(static_cast<size_t>(values));
  std::iota(pool.begin(), pool.end(), 1);
  // Every ordered choice of `living` values from the pool.
  std::vector<int> pick(living);
  std::vector<bool> used(pool.size(), false);
  const auto choose = [&](auto&& self, size_t depth) -> void {
    if (depth == living) {
      std::vector<int> map{0};
      map.insert(map.end(), pick.begin(), pick.end());
      out.push_back(map);
      return;
    }
    for (size_t v = 0; v < pool.size(); ++v) {
      if (used[v]) continue;
      used[v] = true, pick[depth] = pool[v];
      self(self, depth + 1);
      used[v] = false;
    }
  };
  choose(choose, 0);
  return out;
}

std::string overlay_words(const std::vector<int>& value_of, const std::vector<std::string>& states,
                          int curds) {
  std::string s = fmt::format("{} overlaid curds (", curds);
  for (size_t t = 1; t < value_of.size(); ++t) {
    std::string bits;
    for (int c = 0; c < curds; ++c)
      if (value_of[t] >> c & 1) bits += (bits.empty() ? "" : "+") + std::to_string(c + 1);
    s += (t > 1 ? ", " : "") + states[t - 1] + " = curd " + bits;
  }
  return s + ")";
}

// The fitted chain as the engine's (markov.h), for its theory.
MarkovChain chain_of(const ChainReading& c, int stages) {
  MarkovChain m;
  m.states = c.states;
  m.colours.assign(c.states.size(), std::nullopt);
  const ChainValues v = c.fit.values(stages);
  auto probabilities = [](const std::vector<double>& row) {
    std::vector<Probability> out;
    for (const double x : row) out.push_back(*Probability::from_double(std::clamp(x, 0.0, 1.0)));
    return out;
  };
  m.start = probabilities(v.start);
  for (const auto& matrix : v.transitions) {
    m.transitions.emplace_back();
    for (const auto& row : matrix) m.transitions.back().push_back(probabilities(row));
  }
  return m;
}

std::vector<StateLevel> state_levels(const ChainReading& c, const StateTree& tree, const Lattice& l,
                                     const Box& view) {
  const size_t S = c.states.size() + 1;
  const int K = l.stages;
  const MarkovChain chain = chain_of(c, K);
  const StateTreeCounts seen = tree.expected_counts(c.fit.values(K));
  std::vector<StateLevel> levels(static_cast<size_t>(K) + 1);
  for (int m = 0; m <= K; ++m) {
    StateLevel& at = levels[static_cast<size_t>(m)];
    at.level = m;
    at.cells.assign(S, 0.0);
    if (m == 0) {
      at.cells = seen.roots;
    } else {
      for (size_t i = 0; i < S; ++i)
        for (size_t j = 0; j < S; ++j) at.cells[j] += seen.steps[static_cast<size_t>(m) - 1][i][j];
    }
    const double C = static_cast<double>(cells_meeting(l, m, view));
    for (const double share : state_shares(chain, m)) at.expected_cells.push_back(C * share);
    at.boxes.assign(S, 0);
    at.expected_boxes.assign(S, 0.0);
  }
  for (size_t j = 1; j < S; ++j) {
    std::vector<bool> targets(S, false);
    targets[j] = true;
    const std::vector<double> expected = expected_state_box_counts(l, chain, targets, view);
    std::vector<bool> held(tree.leaves());
    for (size_t i = 0; i < held.size(); ++i) held[i] = tree.leaf(i) == j;
    for (int m = K; m >= 0; --m) {
      StateLevel& at = levels[static_cast<size_t>(m)];
      at.boxes[j] = static_cast<uint64_t>(std::count(held.begin(), held.end(), true));
      at.expected_boxes[j] = expected[static_cast<size_t>(m)];
      if (m == 0) break;
      std::vector<bool> up(tree.cells(m - 1), false);
      for (size_t i = 0; i < held.size(); ++i)
        if (held[i]) up[tree.parent(m, i)] = true;
      held.swap(up);
    }
  }
  return levels;
}

}  // namespace

double overlay_log_likelihood(const Lattice& l, const Box& view, const std::vector<uint8_t>& tones,
                              const std::vector<int>& value_of, int curds) {
  ChainFitOptions one;
  one.stage_wise = true;
  one.start_state = 1;
  one.intervals = false;
  double sum = 0;
  std::vector<uint8_t> bits(tones.size());
  for (int c = 0; c < curds; ++c) {
    for (size_t i = 0; i < tones.size(); ++i)
      bits[i] = static_cast<uint8_t>(value_of[tones[i]] >> c & 1);
    sum += fit_chain(StateTree(l, view, bits, 2), one).log_likelihood;
  }
  return sum;
}

ChainReading read_as_chain(ChainRequest r) {
  if (r.tones.size() > kMostChainCells)
    throw ResourceLimitError(fmt::format(
        "a chain is fitted to at most {} cells; this has {}: fit a part of it, or cells of more "
        "pixels (--cell-pixels)",
        kMostChainCells, r.tones.size()));
  const int most = r.tones.empty() ? 0 : *std::max_element(r.tones.begin(), r.tones.end());
  if (most >= kMostTones)
    throw InputError(parameter("states"),
                     fmt::format("a chain of at most {} living states; the cells have {}",
                                 kMostTones - 1, most));
  const size_t living = std::max<size_t>(r.states.size(), static_cast<size_t>(most));
  if (living < 1)
    throw InputError(parameter("states"), "the cells hold no living state: nothing to fit");
  // The tree's tables: each coarser cell's state chances up and down (3 x 8 bytes a state) and
  // its parent (4 bytes), each finest cell's state and parent (5 bytes).
  const double B = static_cast<double>(r.lattice.children());
  const double coarser = static_cast<double>(r.tones.size()) / std::max(1.0, B - 1) + 1;
  const double bytes = coarser * (24.0 * static_cast<double>(living + 1) + 4) +
                       5.0 * static_cast<double>(r.tones.size());
  const uint64_t limit = r.max_memory ? r.max_memory : default_memory_limit();
  if (bytes > static_cast<double>(limit))
    throw ResourceLimitError(fmt::format(
        "fitting a chain of {} states to {} cells takes about {:.0f} MiB, over the limit of "
        "{:.0f} MiB: fit fewer cells (--cell-pixels, a part of the picture) or allow more memory "
        "(--max-memory)",
        living, r.tones.size(), bytes / 1048576, static_cast<double>(limit) / 1048576));
  ChainReading out;
  out.curd = r.curd;
  out.states = r.states;
  for (size_t s = out.states.size(); s < living; ++s)
    out.states.push_back("tone-" + std::to_string(s + 1));
  out.colours = r.colours;
  out.colours.resize(living);
  // One state is a plain curd: every root alive, a probability per stage.
  out.options.stage_wise = r.stage_wise || living == 1;
  out.options.wheys = r.wheys;
  out.options.intervals = r.intervals;
  if (living == 1) out.options.start_state = 1;
  const StateTree tree(r.lattice, r.view, r.tones, living + 1);
  out.fit = fit_chain(tree, out.options);
  out.readings.push_back(
      {"chain",
       fmt::format("one Markov curd of {} living state{}{}{}", living, living == 1 ? "" : "s",
                   out.options.stage_wise ? ", a matrix per stage" : ", one matrix",
                   out.options.wheys ? ", wheys" : ""),
       out.fit.log_likelihood, out.fit.parameters, out.fit.bic});
  out.supported = "chain";
  if (r.intervals) out.levels = state_levels(out, tree, r.lattice, r.view);
  if (living == 1) return out;  // the overlay of one curd is this same model
  const int curds = static_cast<int>(std::bit_width(living));
  double best = -INFINITY;
  std::vector<int> best_map;
  for (const std::vector<int>& map : assignments(living, curds)) {
    const double l = overlay_log_likelihood(r.lattice, r.view, r.tones, map, curds);
    if (l > best) best = l, best_map = map;
  }
  const int d = curds * r.lattice.stages;
  out.readings.push_back({"overlay", overlay_words(best_map, out.states, curds), best, d,
                          information_criterion(best, d, tree.leaves())});
  const bool chain_wins = out.readings[0].bic <= out.readings[1].bic;
  out.supported = chain_wins ? "chain" : "overlay";
  out.margin = std::fabs(out.readings[0].bic - out.readings[1].bic);
  return out;
}

std::string chain_recipe_toml(const ChainReading& c, int stages) {
  const ChainFit& f = c.fit;
  std::string t = "\n[[curds]]\nname = " + toml_quoted(c.curd) + "\n";
  if (c.states.size() == 1) {
    // The plain curd: P_k[1][1] at each stage.
    std::string p, ranges;
    for (size_t k = 0; k < f.transitions.size(); ++k) {
      const FittedEntry& e = f.transitions[k][1][1];
      p += (k ? ", " : "") + row_texts(f.transitions[k][1])[1];
      ranges += fmt::format("{}{}", k ? ", " : "", interval_text(e));
    }
    t += "# 95 % intervals by stage: " + ranges + "\n";
    t += "probabilities = [" + p + "]\n";
    if (!c.colours[0].empty()) t += "colour = " + toml_quoted(c.colours[0]) + "\n";
    return t;
  }
  t += "states = " + quoted_list(c.states) + "\n";
  if (std::none_of(c.colours.begin(), c.colours.end(), [](const auto& s) { return s.empty(); }))
    t += "colours = " + quoted_list(c.colours) + "\n";
  std::vector<std::string> start = row_texts(f.start);
  start.erase(start.begin());  // dead: a root is never dead
  std::string ranges;
  for (size_t j = 1; j < f.start.size(); ++j)
    ranges += (j > 1 ? ", " : "") + interval_text(f.start[j]);
  t += "# start, 95 % intervals: " + ranges + "\n";
  t += "start = " + quoted_list(start) + "\n";
  t += "# rows and columns: dead, " + fmt::format("{}", fmt::join(c.states, ", ")) + "\n";
  t += "transitions = [\n";
  for (size_t k = 0; k < f.transitions.size(); ++k) {
    if (f.transitions.size() > 1) t += fmt::format("  # stage {}\n", k + 1);
    t += "  [\n";
    for (size_t i = 0; i < f.transitions[k].size(); ++i) {
      const auto& row = f.transitions[k][i];
      std::string within;
      for (size_t j = 0; j < row.size(); ++j) within += (j ? ", " : "") + interval_text(row[j]);
      t += "    " + quoted_list(row_texts(row)) + ",  # 95 %: " + within + "\n";
    }
    t += "  ],\n";
  }
  t += "]\n";
  if (f.transitions.size() == 1) t += fmt::format("stages = {}\n", stages);
  return t;
}

json chain_reading_json(const ChainReading& c, int stages) {
  auto entries = [](const std::vector<FittedEntry>& row) {
    json out = json::array();
    const std::vector<std::string> texts = row_texts(row);
    for (size_t j = 0; j < row.size(); ++j)
      out.push_back({{"value", row[j].value},
                     {"text", texts[j]},
                     {"low", row[j].low},
                     {"high", row[j].high},
                     {"fixed", row[j].fixed}});
    return out;
  };
  json matrices = json::array();
  for (const auto& m : c.fit.transitions) {
    json rows = json::array();
    for (const auto& row : m) rows.push_back(entries(row));
    matrices.push_back(rows);
  }
  json readings = json::array();
  for (const Reading& r : c.readings)
    readings.push_back({{"name", r.name},
                        {"what", r.what},
                        {"log_likelihood", r.log_likelihood},
                        {"parameters", r.parameters},
                        {"bic", r.bic}});
  json levels = json::array();
  for (const StateLevel& l : c.levels)
    levels.push_back({{"level", l.level},
                      {"cells", l.cells},
                      {"expected_cells", l.expected_cells},
                      {"boxes", l.boxes},
                      {"expected_boxes", l.expected_boxes}});
  return {{"curd", c.curd},
          {"states", c.states},
          {"colours", c.colours},
          {"stage_wise", c.options.stage_wise},
          {"wheys", c.options.wheys},
          {"start", entries(c.fit.start)},
          {"transitions", matrices},
          {"stages", stages},
          {"converged", c.fit.converged},
          {"intervals", c.fit.intervals},
          {"readings", readings},
          {"supported", c.supported},
          {"margin", c.margin},
          {"levels", levels}};
}

}  // namespace curdle::app
