// Seed and segment search: many seeds of one design, each scored over segments of its view
// against the designer's targets, the best kept. What `curdle search` and the page's search
// run. Targets are text ("ratio:dark=0.11", "cluster:dark<=12", "empty=0,0,8,8"), parsed here
// so that the command line, the API and the tests read them one way.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "curdle/curd.h"

namespace curdle {

// sheet_open_area is a layout's measure (the open share of each fabrication sheet of a
// perforated surface): the layers above supply it through SearchSpec::sheet_open_areas.
enum class Measure { count, ratio, dimension, cluster, run, lacunarity, empty, sheet_open_area };
enum class Compare { equal, at_most, at_least, within };

struct Target {
  std::string text;  // as written, for reports
  Measure measure = Measure::ratio;
  int subject = 0;  // a value; for dimension, and empty with a curd, the curd (-1: any curd)
  Compare compare = Compare::equal;
  double goal = 0;
  double goal_high = 0;  // within: goal to goal_high
  Box zone;              // empty: the zone, cells from the segment's corner
};

// The syntax, for help texts and error messages.
extern const char* const kTargetSyntax;

// Throws InputError naming the target and what is allowed.
Target parse_target(const std::string& text, const Design& design);

// Targets used when none are given: every value at its expected share (the products of the
// curds' final probabilities) and every curd at the dimension its probabilities imply.
std::vector<Target> default_targets(const Design& design);

struct SearchSpec {
  std::vector<Target> targets;
  std::optional<std::array<int64_t, 2>> window;  // segment size in cells; none: the whole view
  int64_t stride = 0;                            // between segment corners; 0: size / 8
  int top = 10;
  int64_t lacunarity_box = 0;  // 0: the base b
  // The open share of every fabrication sheet when the segment of this seed's curds is laid
  // out; called from many threads at once. Needed by sheet_open_area targets.
  std::function<std::vector<double>(const CurdField& field, const Box& segment)> sheet_open_areas;
};

struct SearchHit {
  uint64_t seed = 0;
  Box segment;
  double score = 0;              // sum of the targets' shortfalls; 0 meets every target
  std::vector<double> measured;  // per target (NaN when undefined, e.g. no survivor)
  bool meets_empty_zones = true;
  // How far inside its bounds the tightest <=, >= or range target is (every sheet's, for
  // sheet_open_area), in the units of its shortfall: what ranks hits of equal score (82 seeds
  // passing a sheet's open-area band all scored 0 and nothing ranked them). Infinite when
  // there is no such target.
  double margin = std::numeric_limits<double>::infinity();
};

// How far `measured` misses the target: |x - goal| for ratios, dimensions and open areas,
// relative for counts, clusters, runs and lacunarity, only the excess or shortfall for <=, >=
// and a range; an empty zone adds 100 times the share of its cells that are occupied.
double shortfall(const Target& target, double measured);

// How far inside its bound(s) `measured` is for a <=, >= or range target (negative outside),
// relative as the shortfall is; infinite for the other targets.
double margin(const Target& target, double measured);

// Of the sheets' open shares, the one that misses `target` most (the first of equals): what a
// sheet_open_area target measures, so that it is met only when every sheet meets it.
double worst_sheet(const Target& target, const std::vector<double>& shares);

// The measure of `target` on a segment of a curd (see segment_measures.h).
class SegmentMeasures;
double measure(const Target& target, SegmentMeasures& measures, const Design& design,
               const Box& segment, int64_t lacunarity_box);

// Checks the spec against the design and view (2-D or 1-D lattice; window inside the view;
// zones inside the window); throws InputError.
void check_search(const Design& design, const Box& view, const SearchSpec& spec);

// Every seed from `first` to `last` (inclusive), each with its best segment; the `top` best
// seeds, best first (ties: lower seed, then lower segment corner). Runs on all TBB threads;
// the result does not depend on their number. `cancel`, when set, stops early with what was
// found so far.
std::vector<SearchHit> search_seeds(const Design& design, const Box& view, const SearchSpec& spec,
                                    uint64_t first, uint64_t last,
                                    const std::function<void(double)>& progress = {},
                                    const std::atomic<bool>* cancel = nullptr);

}  // namespace curdle
