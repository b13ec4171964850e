// Exceptions become exit codes here and only here: 2 for bad input (including a resource
// limit), 1 for an internal failure. Both programs, curdle and curdle-serve, end through it.
#pragma once

#include <cstdio>
#include <functional>
#include <new>

#include "cli/options.h"
#include "curdle/error.h"

namespace curdle::cli {

inline int exit_code(const std::function<int()>& run) {
  try {
    return run();
  } catch (const InputError& e) {
    std::fprintf(stderr, "curdle: error: %s\n", render_error(e, option_name).c_str());
    return 2;
  } catch (const std::bad_alloc&) {
    // Bad input too: a request larger than the memory the process may have (a ulimit, a
    // container's limit, the machine), refused when it asked for it.
    std::fprintf(stderr,
                 "curdle: error: out of memory: the system refused memory this run asked for "
                 "(above what a ulimit, a container or the machine allows); ask for less: a "
                 "smaller field, window, layout or picture, or give --max-memory a limit the "
                 "machine can meet so that curdle refuses such runs before it starts\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "curdle: internal error: %s\n", e.what());
    return 1;
  }
}

}  // namespace curdle::cli
