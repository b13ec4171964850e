// `curdle search`: many seeds of a recipe ranked by how well their segments meet targets,
// the best printed with their scores and the command that reproduces each, their previews and
// a CSV of all written. The page's search answers with the same JSON.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/session.h"
#include "curdle/search.h"

namespace curdle::cli {

struct SearchOptions {
  std::string recipe_path;
  std::vector<std::string> sets;
  std::string seeds;   // "A..B", inclusive, or one seed
  std::string window;  // "W,H" (1-D: "W"): segment size in cells
  int64_t stride = 0;
  std::vector<std::string> targets;
  int top = 10;
  int64_t lacunarity_box = 0;
  std::string out_dir;
  bool previews = true;
  int threads = 0;
  std::string max_memory;
};

void add_search_options(CLI::App& command, SearchOptions& options);
int run_search(const SearchOptions& options);

// "A..B" or "N"; throws InputError naming `option`.
std::pair<uint64_t, uint64_t> parse_seed_range(const std::string& text, const std::string& option);
// "W,H" (or "W" on a 1-D lattice); throws InputError naming `option`.
std::array<int64_t, 2> parse_segment_size(const std::string& text, int dimension,
                                          const std::string& option);

// A search spec for a session: targets parsed, the segment size given or, for a fixed floor
// laid from a larger field, the floor's. Throws InputError.
SearchSpec make_search_spec(const Session& session, const std::vector<std::string>& targets,
                            const std::string& window, int64_t stride, int top,
                            int64_t lacunarity_box);

// Hits as JSON: rank, seed, segment, score, measures per target, and the generate command that
// reproduces each.
nlohmann::ordered_json search_hits_json(const Session& session, const std::vector<std::string>& sets,
                                        const SearchSpec& spec, const std::vector<SearchHit>& hits);

}  // namespace curdle::cli
