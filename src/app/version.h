// The version of libcurdle.so, as its package (curdleConfigVersion.cmake) gives it: defined in
// the shared library alone.
#pragma once

namespace curdle::app {

const char* version();

}  // namespace curdle::app
