#include "cli/options.h"

namespace curdle::cli {

const CLI::Validator kNotEmpty(
    [](std::string& value) {
      return value.empty() ? std::string("is empty; give a value or leave the option out")
                           : std::string();
    },
    "", "not empty");

void add_common_options(CLI::App& c, CommonOptions& o) {
  c.add_option("recipe", o.recipe_path,
               "Recipe file (TOML), e.g. patterns/paper/fig3-two-curds.toml")
      ->required();
  c.add_option("--seed", o.seed, "Random seed, 0 to 2^64-1 (default: the recipe's `seed`, else 1)")
      ->check(kNotEmpty);
  c.add_option("--set", o.sets,
               "Override a recipe key: --set lattice.mode=exact, "
               "--set curds.0.probabilities='[\"1/2\",\"1/2\"]'")
      ->allow_extra_args(false);  // one value each time, so the recipe may follow
  c.add_option("--window", o.window,
               "Segment of the field in cells: X,Y,W,H (1-D X,W; 3-D X,Y,Z,W,H,D)")
      ->check(kNotEmpty);
  c.add_option("--threads", o.threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  c.add_option("--max-memory", o.max_memory,
               "Refuse work above this much memory, e.g. 8G "
               "(default: half the physical memory)")
      ->check(kNotEmpty);
}

app::RunRequest run_request(const CommonOptions& o) {
  app::RunRequest r;
  r.recipe_path = o.recipe_path;
  r.recipe_text = app::read_recipe_file(o.recipe_path);
  r.overrides = o.sets;
  r.seed = o.seed;
  r.window = o.window;
  if (!o.max_memory.empty()) r.max_memory = app::parse_bytes(o.max_memory, "max_memory");
  r.memory_limit_hint = "raise the limit with --max-memory";
  return r;
}

std::string option_name(const std::string& parameter) {
  if (parameter == "segment") return "--window";
  std::string name = "--" + parameter;
  for (char& c : name)
    if (c == '_') c = '-';
  return name;
}

}  // namespace curdle::cli
