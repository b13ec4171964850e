// The options `generate` and `report` share, and how the command line spells run parameters.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "app/run.h"

namespace curdle::cli {

struct CommonOptions {
  std::string recipe_path;
  std::string seed;  // checked by the application: a whole number from 0 to 2^64 - 1
  std::vector<std::string> sets;
  std::string window;
  int threads = 0;  // 0: all cores
  std::string max_memory;
};

void add_common_options(CLI::App& command, CommonOptions& options);

// Reads the recipe file and turns the options into a run request.
app::RunRequest run_request(const CommonOptions& options);

// Refuses a value given as '' (which would otherwise read as "not given").
extern const CLI::Validator kNotEmpty;

// "--window" for the parameter "window"; `search` spells the segment size --window too.
std::string option_name(const std::string& parameter);

}  // namespace curdle::cli
