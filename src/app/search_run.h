// A seed search as both shells run it: the request's text checked into a spec, its memory
// counted, the search run, and its hits as JSON, search.csv and previews.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/output_sink.h"
#include "app/run.h"
#include "curdle/search.h"

namespace curdle::app {

struct SearchRequest {
  RunRequest run;
  std::string seeds = "1..1000";  // "A..B", inclusive, or one seed
  std::string segment;            // "W,H" (1-D "W"); empty: the recipe's window, or the field
  std::vector<std::string> targets;
  int64_t stride = 0;
  int top = 10;
  int64_t lacunarity_box = 0;
  int threads = 0;  // 0: all cores; counted in the memory estimate
  // Most work one search may do, in cell-stages (seeds x field cells x stages): a budget
  // that both shells enforce, so that no request runs for hours.
  uint64_t max_work = kDefaultSearchWork;
  static constexpr uint64_t kDefaultSearchWork = uint64_t{1} << 42;
};

struct SearchRun {
  Run run;
  SearchSpec spec;
  uint64_t first = 0, last = 0;
};

// What a seed costs beyond its cells, in cell-stages: drawing, scoring and ranking it. Without
// it a search of 2^28 seeds of a one-cell field passed the budget and ran for minutes.
inline constexpr uint64_t kSeedWork = 1024;

// Cell-stages a search of these seeds does: seeds x (field cells x stages + kSeedWork),
// saturating.
uint64_t search_work(const Design& design, uint64_t first, uint64_t last);

// Checks everything, the work budget and the memory the threads need together; InputError naming
// the parameter ("seeds", "segment", "target", ...), ResourceLimitError above the memory limit.
SearchRun resolve_search(const SearchRequest& request);

// "A..B" or "N"; InputError naming `name`.
std::pair<uint64_t, uint64_t> parse_seed_range(const std::string& text, const std::string& name);
// "W,H" (or "W" on a 1-D lattice); InputError naming `name`.
std::array<int64_t, 2> parse_segment_size(const std::string& text, int dimension,
                                          const std::string& name);

std::vector<SearchHit> run_search(const SearchRun& search,
                                  const std::function<void(double)>& progress = {},
                                  const std::atomic<bool>* cancel = nullptr);

// Hits as JSON: targets, then per hit its rank, seed (as a string: JavaScript numbers lose
// seeds above 2^53), segment, score, measures and the command that reproduces it.
nlohmann::ordered_json search_hits_json(const SearchRun& search,
                                        const std::vector<SearchHit>& hits);

// search.csv or a preview (rank-01-seed-7.png): what a search's directory may hold.
bool is_search_output_name(const std::string& name, bool folder);

// search.csv, and with `previews` a preview PNG of each hit's segment, to `sink`.
// Returns the previews' names.
std::vector<std::string> write_search_outputs(const SearchRun& search,
                                              const std::vector<SearchHit>& hits,
                                              const nlohmann::ordered_json& hits_json,
                                              bool previews, OutputSink& sink);

}  // namespace curdle::app
