// `curdle generate` without the command line: a session's outputs written into a directory,
// all or nothing. The page's downloads come from here too, so they are the CLI's files.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/session.h"

namespace curdle::cli {

// Writes the outputs named (none: all but layout.gltf) into `dir`, staged and renamed together
// once all succeeded. Prints a summary to `log` and progress to a terminal (nullptr: silent,
// as the server runs it). Returns the files written.
// Throws InputError for bad input, before anything is written.
std::vector<std::filesystem::path> write_outputs(Session& session, const std::filesystem::path& dir,
                                                 const std::vector<std::string>& outputs_named,
                                                 int threads, FILE* log);

}  // namespace curdle::cli
