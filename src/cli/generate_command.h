// `curdle generate` and `curdle report`: a run's outputs written into a directory, or its
// per-stage report printed.
#pragma once

#include <string>
#include <vector>

#include "cli/options.h"

namespace curdle::cli {

int run_generate(const CommonOptions& options, const std::string& out_dir,
                 const std::vector<std::string>& outputs);
int run_report(const CommonOptions& options);

// "report.json, cells.csv, ... (default: ...)" from the registry, for --help.
std::string outputs_help();

}  // namespace curdle::cli
