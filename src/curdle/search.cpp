#include "curdle/search.h"

#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <limits>

#include "curdle/boxcount.h"
#include "curdle/curdling.h"
#include "curdle/error.h"
#include "curdle/markov.h"
#include "curdle/overlay.h"
#include "curdle/segment_measures.h"
#include "curdle/stop.h"
#include "curdle/theory.h"

namespace curdle {

const char* const kTargetSyntax =
    "MEASURE:SUBJECT=GOAL (or <= or >=, or =LOW..HIGH for a range), MEASURE one of count, "
    "ratio, dimension, cluster, run, "
    "lacunarity, SUBJECT a value (its number or label, e.g. dark+light) or for dimension a "
    "curd; or empty[:CURD]=X,Y,W,H, a zone of cells from the segment's corner that must hold "
    "no survivor; or, on a perforated layout, sheet_open_area=LOW..HIGH (or <=, >= or = a "
    "share from 0 to 1), the open share every fabrication sheet must have";

namespace {

const SourceLocation kWhere = parameter("target");

[[noreturn]] void fail(const std::string& text, const std::string& why) {
  std::string message = "'";
  message += text;
  message += "': ";
  message += why;
  throw InputError(kWhere, message);
}

int parse_value(const std::string& text, const std::string& name, const Design& d) {
  const int values = 1 << d.curds.size();
  if (name.empty()) {
    if (d.curds.size() == 1) return 1;
    fail(text, "name the value, e.g. ratio:" + value_label(1, d.curds) + "=0.1");
  }
  int v = -1;
  auto [p, ec] = std::from_chars(name.data(), name.data() + name.size(), v);
  if (ec == std::errc() && p == name.data() + name.size() && v >= 0 && v < values) return v;
  std::string labels;
  for (int u = 0; u < values; ++u) {
    if (value_label(static_cast<uint32_t>(u), d.curds) == name) return u;
    labels += (u ? ", " : "") + value_label(static_cast<uint32_t>(u), d.curds);
  }
  fail(text, "no value '" + name + "'; the values are 0 to " + std::to_string(values - 1) +
                 " or their labels: " + labels);
}

int parse_curd(const std::string& text, const std::string& name, const Design& d) {
  // A Markov curd's planes are not sets of their own: its states are measured by ratio.
  std::string names;
  int only = -1, plain = 0;
  for (size_t c = 0; c < d.curds.size(); ++c) {
    if (d.curds[c].chain) {
      if (d.curds[c].plane == 0 && d.curds[c].name == name)
        fail(text, "'" + name + "' is a Markov curd; aim at its states by ratio, e.g. ratio:" +
                       d.curds[c].chain->states[0] + "=0.2");
      continue;
    }
    if (d.curds[c].name == name || std::to_string(c) == name) return static_cast<int>(c);
    names += (plain++ ? ", " : "") + d.curds[c].name;
    only = static_cast<int>(c);
  }
  if (name.empty() && plain == 1) return only;
  if (name.empty() && plain > 1)
    fail(text, "name the curd, e.g. dimension:" + names.substr(0, names.find(',')) + "=1.5");
  if (plain == 0) fail(text, "a dimension target needs a plain curd, and this recipe has none");
  fail(text, "no curd '" + name + "'; the curds are " + names);
}

double parse_number(const std::string& text, const std::string& number) {
  double x = 0;
  auto [p, ec] = std::from_chars(number.data(), number.data() + number.size(), x);
  if (ec != std::errc() || p != number.data() + number.size() || !std::isfinite(x) || x < 0)
    fail(text, "the goal '" + number + "' is not a number from 0 up");
  return x;
}

// GOAL, or LOW..HIGH for a range (every measure takes one): numbers from 0 up.
void parse_goal(const std::string& text, const std::string& goal, Target& t) {
  const size_t dots = goal.find("..");
  if (dots == std::string::npos) {
    t.goal = t.goal_high = parse_number(text, goal);
    return;
  }
  if (t.compare != Compare::equal)
    fail(text, "a range is written MEASURE:SUBJECT=LOW..HIGH, with = alone");
  t.compare = Compare::within;
  t.goal = parse_number(text, goal.substr(0, dots));
  t.goal_high = parse_number(text, goal.substr(dots + 2));
  if (t.goal_high < t.goal) fail(text, "a range runs from its low end to its high end");
}

bool before(const SearchHit& a, const SearchHit& b) {
  if (a.score != b.score) return a.score < b.score;
  // Equal scores (every target met, say): the one further inside its bounds first.
  if (a.margin != b.margin) return a.margin > b.margin;
  if (a.seed != b.seed) return a.seed < b.seed;
  if (a.segment.origin[1] != b.segment.origin[1]) return a.segment.origin[1] < b.segment.origin[1];
  return a.segment.origin[0] < b.segment.origin[0];
}

void keep_best(std::vector<SearchHit>& best, SearchHit hit, size_t top) {
  if (best.size() == top && !before(hit, best.back())) return;
  best.insert(std::upper_bound(best.begin(), best.end(), hit, before), std::move(hit));
  if (best.size() > top) best.pop_back();
}

// Corners of the segments along one axis: every `stride` from 0, and the last one flush with
// the far edge so that no part of the view is left out.
std::vector<int64_t> corners(int64_t view, int64_t size, int64_t stride) {
  std::vector<int64_t> c;
  for (int64_t x = 0; x + size <= view; x += stride) c.push_back(x);
  if (c.empty() || c.back() != view - size) c.push_back(view - size);
  return c;
}

// Per thread: the curds of one seed and the measures over its view.
struct Scorer {
  CurdField field;
  SegmentMeasures measures;
  std::vector<Bitset> scratch;
  std::vector<uint64_t> counts, box_counts;
  std::vector<double> measured;
};

bool needs_grid(const SearchSpec& spec) {
  if (spec.window) return true;
  for (const Target& t : spec.targets)
    if (t.measure != Measure::count && t.measure != Measure::ratio &&
        t.measure != Measure::dimension)
      return true;
  return false;
}

// The whole generated view, read off the bitsets without a grid of values. Writes the
// measures into s.measured and returns the score; allocates nothing once warm.
double score_bitsets(const Design& d, const SearchSpec& spec, Scorer& s) {
  const size_t n = d.curds.size(), values = size_t{1} << n;
  const double cells = static_cast<double>(s.field.generated.cells());
  s.counts.assign(values, 0);
  s.measured.clear();
  bool counted = false;
  double score = 0;
  for (const Target& t : spec.targets) {
    double x = std::numeric_limits<double>::quiet_NaN();
    if (t.measure == Measure::dimension) {
      box_counts_into(s.field.curds[static_cast<size_t>(t.subject)], d.lattice.children(),
                      s.scratch, s.box_counts);
      const auto fit = fit_box_dimension(s.box_counts, d.lattice.base);
      if (fit) x = fit->slope;
    } else {
      if (!counted) {
        const size_t words = s.field.finest(0).words.size();
        for (size_t w = 0; w < words; ++w)
          for (size_t v = 1; v < values; ++v) {
            uint64_t m = ~uint64_t{0};
            for (size_t c = 0; c < n; ++c)
              m &= (v >> c & 1) ? s.field.finest(c).words[w] : ~s.field.finest(c).words[w];
            s.counts[v] += static_cast<uint64_t>(std::popcount(m));
          }
        uint64_t occupied = 0;
        for (size_t v = 1; v < values; ++v) occupied += s.counts[v];
        s.counts[0] = s.field.generated.cells() - occupied;
        counted = true;
      }
      x = static_cast<double>(s.counts[static_cast<size_t>(t.subject)]);
      if (t.measure == Measure::ratio) x /= cells;
    }
    s.measured.push_back(x);
    score += shortfall(t, x);
  }
  return score;
}

}  // namespace

Target parse_target(const std::string& text, const Design& d) {
  Target t;
  t.text = text;
  size_t op = text.find_first_of("<>=");
  if (op == std::string::npos) fail(text, std::string("not a target; write ") + kTargetSyntax);
  std::string head = text.substr(0, op), goal;
  if (text[op] == '=') {
    goal = text.substr(op + 1);
  } else {
    if (op + 1 >= text.size() || text[op + 1] != '=')
      fail(text, "write <= or >=, or = for a goal to meet as closely as possible");
    t.compare = text[op] == '<' ? Compare::at_most : Compare::at_least;
    goal = text.substr(op + 2);
  }
  const size_t colon = head.find(':');
  const std::string kind = head.substr(0, colon);
  const std::string subject = colon == std::string::npos ? "" : head.substr(colon + 1);
  static const std::pair<const char*, Measure> kinds[] = {
      {"count", Measure::count},
      {"ratio", Measure::ratio},
      {"dimension", Measure::dimension},
      {"cluster", Measure::cluster},
      {"run", Measure::run},
      {"lacunarity", Measure::lacunarity},
      {"empty", Measure::empty},
      {"sheet_open_area", Measure::sheet_open_area}};
  const auto k = std::find_if(std::begin(kinds), std::end(kinds),
                              [&](const auto& p) { return kind == p.first; });
  if (k == std::end(kinds))
    fail(text, "unknown measure '" + kind +
                   "'; the measures are count, ratio, dimension, cluster, run, lacunarity, "
                   "empty, sheet_open_area");
  t.measure = k->second;
  if (t.measure == Measure::sheet_open_area) {
    if (!subject.empty()) fail(text, "sheet_open_area takes no subject: every sheet is measured");
    parse_goal(text, goal, t);
    if (t.goal > 1 || t.goal_high > 1) fail(text, "an open share is from 0 to 1");
    return t;
  }
  if (t.measure == Measure::empty) {
    if (t.compare != Compare::equal) fail(text, "an empty zone is written empty[:CURD]=X,Y,W,H");
    t.subject = subject.empty() ? -1 : parse_curd(text, subject, d);
    std::array<int64_t, 4> v{};
    size_t start = 0;
    for (int i = 0; i < 4; ++i) {
      const size_t end = i < 3 ? goal.find(',', start) : goal.size();
      if (end == std::string::npos) fail(text, "the zone must be X,Y,W,H in cells");
      auto [p, ec] =
          std::from_chars(goal.data() + start, goal.data() + end, v[static_cast<size_t>(i)]);
      if (ec != std::errc() || p != goal.data() + end ||
          v[static_cast<size_t>(i)] < (i < 2 ? 0 : 1))
        fail(text, "the zone must be X,Y,W,H in whole cells, sizes at least 1");
      start = end + 1;
    }
    t.zone.origin = {v[0], v[1], 0};
    t.zone.size = {v[2], v[3], 1};
    if (!t.zone.well_formed())
      fail(text, "the zone must have origins from 0 and sizes from 1, each at most 2^40 cells");
    return t;
  }
  t.subject = t.measure == Measure::dimension ? parse_curd(text, subject, d)
                                              : parse_value(text, subject, d);
  parse_goal(text, goal, t);
  if (t.measure == Measure::ratio && t.goal_high > 1) fail(text, "a ratio is from 0 to 1");
  return t;
}

std::vector<Target> default_targets(const Design& d) {
  std::vector<Target> targets;
  const size_t n = d.curds.size();
  const int K = d.lattice.stages;
  std::vector<double> final_p(n);
  for (size_t c = 0; c < n; ++c) final_p[c] = survival_probability(d.curds[c].probabilities, K);
  const std::vector<double> shares = expected_value_shares(d);
  const bool has_markov =
      std::any_of(d.curds.begin(), d.curds.end(), [](const CurdSpec& c) { return c.chain; });
  for (uint32_t v = 0; v < (uint32_t{1} << n); ++v) {
    Target t;
    t.measure = Measure::ratio;
    t.subject = static_cast<int>(v);
    t.goal = shares[v];
    // A code a Markov curd's planes can hold but no state has: never there, nothing to aim at.
    if (t.goal == 0 && has_markov) continue;
    t.text = "ratio:" + value_label(v, d.curds) + "=" + std::to_string(t.goal);
    targets.push_back(t);
  }
  for (size_t c = 0; c < n; ++c) {
    if (final_p[c] <= 0 || d.curds[c].chain) continue;  // a Markov curd's sets: by ratio
    Target t;
    t.measure = Measure::dimension;
    t.subject = static_cast<int>(c);
    // E + log P_K / (K log b): the dimension of a constant p with the same final share.
    t.goal = d.lattice.dimension + std::log(final_p[c]) / (K * std::log(d.lattice.base));
    t.text = "dimension:" + d.curds[c].name + "=" + std::to_string(t.goal);
    targets.push_back(t);
  }
  return targets;
}

namespace {

// A distance from a target's bound in the target's terms, so that shortfalls and margins add
// and compare across targets: relative to the goal for counts, clusters, runs and lacunarity,
// as measured for ratios, dimensions and open shares.
double in_target_terms(const Target& t, double distance) {
  const bool relative = t.measure != Measure::ratio && t.measure != Measure::dimension &&
                        t.measure != Measure::sheet_open_area;
  return relative ? distance / std::max(t.goal, 1.0) : distance;
}

}  // namespace

double shortfall(const Target& t, double x) {
  if (t.measure == Measure::empty) return 100 * x / static_cast<double>(t.zone.cells());
  if (std::isnan(x)) return 1;
  const double miss = t.compare == Compare::equal     ? std::fabs(x - t.goal)
                      : t.compare == Compare::at_most ? std::max(0.0, x - t.goal)
                      : t.compare == Compare::within
                          ? std::max(0.0, t.goal - x) + std::max(0.0, x - t.goal_high)
                          : std::max(0.0, t.goal - x);
  return in_target_terms(t, miss);
}

double margin(const Target& t, double x) {
  if (t.measure == Measure::empty || t.compare == Compare::equal || std::isnan(x))
    return std::numeric_limits<double>::infinity();
  const double inside = t.compare == Compare::at_most  ? t.goal - x
                        : t.compare == Compare::within ? std::min(x - t.goal, t.goal_high - x)
                                                       : x - t.goal;
  return in_target_terms(t, inside);
}

double worst_sheet(const Target& t, const std::vector<double>& shares) {
  if (shares.empty()) return std::numeric_limits<double>::quiet_NaN();
  double worst = shares.front();
  for (const double x : shares)
    if (shortfall(t, x) > shortfall(t, worst)) worst = x;
  return worst;
}

double measure(const Target& t, SegmentMeasures& m, const Design& d, const Box& segment,
               int64_t lacunarity_box) {
  const auto value = static_cast<uint32_t>(t.subject);
  switch (t.measure) {
    case Measure::count:
      return static_cast<double>(m.value_count(value, segment));
    case Measure::ratio:
      return static_cast<double>(m.value_count(value, segment)) /
             static_cast<double>(segment.cells());
    case Measure::dimension: {
      const auto fit =
          fit_box_dimension(m.box_counts(static_cast<size_t>(t.subject), segment), d.lattice.base);
      return fit ? fit->slope : std::numeric_limits<double>::quiet_NaN();
    }
    case Measure::cluster:
      return static_cast<double>(m.largest_cluster(value, segment));
    case Measure::run:
      return static_cast<double>(m.longest_run(value, segment));
    case Measure::lacunarity: {
      const auto l = m.lacunarity(value, segment, lacunarity_box);
      return l ? *l : std::numeric_limits<double>::quiet_NaN();
    }
    case Measure::sheet_open_area:
      return std::numeric_limits<double>::quiet_NaN();  // laid out by the caller: search_seeds
    case Measure::empty: {
      Box zone = t.zone;
      zone.origin[0] += segment.origin[0];
      zone.origin[1] += segment.origin[1];
      return t.subject < 0
                 ? static_cast<double>(zone.cells() - m.value_count(0, zone))
                 : static_cast<double>(m.curd_count(static_cast<size_t>(t.subject), zone));
    }
  }
  return 0;
}

void check_search(const Design& d, const Box& view, const SearchSpec& spec) {
  const SourceLocation where;
  if (d.lattice.dimension > 2)
    throw InputError(where, "search works on 1-D and 2-D lattices; this one is 3-D");
  if (spec.top < 1 || spec.top > 1000) throw InputError(parameter("top"), "must be from 1 to 1000");
  if (spec.stride < 0) throw InputError(parameter("stride"), "must be 1 or more");
  if (spec.lacunarity_box < 0)
    throw InputError(parameter("lacunarity_box"), "must be 1 or more cells");
  std::array<int64_t, 2> size{view.size[0], d.lattice.dimension == 2 ? view.size[1] : 1};
  if (spec.window) {
    const auto& w = *spec.window;
    if (w[0] < 1 || w[1] < 1 || w[0] > size[0] || w[1] > size[1])
      throw InputError(parameter("segment"),
                       "a segment of " + std::to_string(w[0]) + " x " + std::to_string(w[1]) +
                           " cells must fit in the view of " + std::to_string(size[0]) + " x " +
                           std::to_string(size[1]) + " cells");
    size = w;
  }
  for (const Target& t : spec.targets)
    if (t.measure == Measure::sheet_open_area && !spec.sheet_open_areas)
      throw InputError(parameter("target"),
                       "'" + t.text +
                           "': sheet_open_area measures the fabrication sheets of a perforated "
                           "layout (layout.kind = \"perforation\"); this recipe has none");
  for (const Target& t : spec.targets)
    if (t.measure == Measure::empty && !Box{{0, 0, 0}, {size[0], size[1], 1}}.contains(t.zone))
      throw InputError(parameter("target"),
                       "'" + t.text + "': the zone must lie inside the segment of " +
                           std::to_string(size[0]) + " x " + std::to_string(size[1]) + " cells");
}

std::vector<SearchHit> search_seeds(const Design& d, const Box& view, const SearchSpec& spec_in,
                                    uint64_t first, uint64_t last,
                                    const std::function<void(double)>& progress,
                                    const std::atomic<bool>* cancel) {
  check_search(d, view, spec_in);
  if (last < first || last - first == UINT64_MAX)
    throw InputError(parameter("seeds"),
                     "a range of seeds runs from its first to its last, and holds fewer than 2^64");
  SearchSpec spec = spec_in;
  if (spec.targets.empty()) spec.targets = default_targets(d);
  if (spec.lacunarity_box == 0) spec.lacunarity_box = d.lattice.base;
  const bool grid = needs_grid(spec);
  const bool one_row = d.lattice.dimension == 1;
  std::vector<Box> segments;
  if (spec.window) {
    const auto [w, h] = *spec.window;
    const int64_t stride = spec.stride ? spec.stride : std::max<int64_t>(1, std::min(w, h) / 8);
    for (int64_t y : corners(one_row ? 1 : view.size[1], h, stride))
      for (int64_t x : corners(view.size[0], w, stride)) {
        Box s = view;
        s.origin[0] += x, s.size[0] = w;
        if (!one_row) s.origin[1] += y, s.size[1] = h;
        segments.push_back(s);
      }
  } else {
    segments.push_back(view);
  }

  const size_t top = static_cast<size_t>(spec.top);
  tbb::combinable<std::vector<SearchHit>> best;
  tbb::combinable<Scorer> scorers;
  const uint64_t total = last - first + 1;
  const uint64_t batch = grid ? 64 : 65536;
  for (uint64_t start = 0; start < total; start += batch) {
    if (cancel && cancel->load()) break;
    stop_point_now();
    const uint64_t end = std::min(total, start + batch);
    tbb::parallel_for(tbb::blocked_range<uint64_t>(start, end, grid ? 1 : 256), [&](auto range) {
      Scorer& s = scorers.local();
      std::vector<SearchHit>& mine = best.local();
      for (uint64_t i = range.begin(); i < range.end(); ++i) {
        const uint64_t seed = first + i;
        curdle_into(d, seed, view, s.field);
        if (!grid && s.field.generated == view) {
          SearchHit hit;
          hit.seed = seed;
          hit.segment = view;
          hit.score = score_bitsets(d, spec, s);
          for (size_t t = 0; t < spec.targets.size(); ++t)
            hit.margin = std::min(hit.margin, margin(spec.targets[t], s.measured[t]));
          // Most seeds lose to the worst kept: skip building their hit.
          if (mine.size() < top || before(hit, mine.back())) {
            hit.measured = s.measured;
            keep_best(mine, std::move(hit), top);
          }
          continue;
        }
        s.measures.reset(d, view, values_in(s.field, view));
        SearchHit best_here;
        bool any = false;
        for (const Box& segment : segments) {
          SearchHit hit;
          hit.seed = seed;
          hit.segment = segment;
          for (const Target& t : spec.targets) {
            double x = 0;
            if (t.measure == Measure::sheet_open_area) {
              const std::vector<double> shares = spec.sheet_open_areas(s.field, segment);
              x = worst_sheet(t, shares);
              for (const double share : shares) hit.margin = std::min(hit.margin, margin(t, share));
            } else {
              x = measure(t, s.measures, d, segment, spec.lacunarity_box);
              hit.margin = std::min(hit.margin, margin(t, x));
            }
            hit.measured.push_back(x);
            hit.score += shortfall(t, x);
            if (t.measure == Measure::empty && x > 0) hit.meets_empty_zones = false;
          }
          if (!any || before(hit, best_here)) best_here = std::move(hit), any = true;
        }
        keep_best(mine, std::move(best_here), top);
      }
    });
    if (progress) progress(static_cast<double>(end) / static_cast<double>(total));
  }
  std::vector<SearchHit> all;
  best.combine_each([&](const std::vector<SearchHit>& part) {
    for (const SearchHit& h : part) keep_best(all, h, top);
  });
  return all;
}

}  // namespace curdle
