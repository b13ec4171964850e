// Tests of search_run.h: seeds, segments and the work budget are checked before a search runs.
#include "app/search_run.h"

#include <gtest/gtest.h>

#include "curdle/error.h"
#include "test_support.h"

namespace curdle::app {
namespace {

TEST(SearchRun, SeedsSegmentsAndTheBudgetAreChecked) {
  EXPECT_EQ(parse_seed_range("5..9", "seeds"), (std::pair<uint64_t, uint64_t>{5, 9}));
  EXPECT_EQ(parse_seed_range("7", "seeds"), (std::pair<uint64_t, uint64_t>{7, 7}));
  EXPECT_EQ(parse_seed_range("0..18446744073709551615", "seeds").second, UINT64_MAX);
  for (const char* bad : {"9..5", "", "1..", "-1..3", "a..b", "1..18446744073709551616"})
    EXPECT_THROW(parse_seed_range(bad, "seeds"), InputError) << bad;
  EXPECT_EQ(parse_segment_size("12,8", 2, "segment"), (std::array<int64_t, 2>{12, 8}));
  EXPECT_THROW(parse_segment_size("12", 2, "segment"), InputError);
  EXPECT_THROW(parse_segment_size("0,8", 2, "segment"), InputError);
  const Design d = test::design(2, 2, {{"3/4", "2/3"}});
  EXPECT_EQ(search_work(d, 1, 10), 10u * (16 * 2 + kSeedWork));
  EXPECT_EQ(search_work(d, 0, UINT64_MAX), UINT64_MAX);  // saturates
  SearchRequest request;
  request.run.recipe_path = "r.toml";
  request.run.recipe_text =
      "[lattice]\nbase = 2\ndimension = 2\n[[curds]]\nprobabilities = [\"3/4\", \"2/3\"]\n";
  request.seeds = "1..1000000";
  request.max_work = 1000;
  EXPECT_THROW(resolve_search(request), ResourceLimitError);
  // Each seed pays its own cost: many seeds of a tiny field are work too.
  request.seeds = "1..268435456";
  request.max_work = uint64_t{1} << 30;
  EXPECT_THROW(resolve_search(request), ResourceLimitError);
  request.max_work = SearchRequest::kDefaultSearchWork;
  request.seeds = "1..20";
  const SearchRun search = resolve_search(request);
  EXPECT_EQ(search.first, 1u);
  EXPECT_EQ(search.last, 20u);
  EXPECT_EQ(run_search(search).size(), 10u);  // the top 10 by default
}

}  // namespace
}  // namespace curdle::app
