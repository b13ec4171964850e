// Ctrl-C and SIGTERM for the command line.
#pragma once

namespace curdle::cli {

// SIGINT and SIGTERM end the program at once with 130 or 143, after removing every staged
// file: an interrupted run leaves the previous output set and no temporary files. Call first
// in main, before any thread starts, so that every thread inherits the blocked signals.
void remove_staged_files_on_interrupt();

}  // namespace curdle::cli
