// curdle's optional modules (libcurdle_image.so with OpenImageIO, libcurdle_gpkg.so with GDAL):
// shared objects loaded the first time they are needed, so that commands that need neither
// start without mapping hundreds of libraries.
#pragma once

#include <string>

namespace curdle {

// The module `file_name` loaded (dlopen), found beside the program (a build tree), in
// ../lib/curdle (installed), beside libcurdle.so or in curdle/ beside it (a program or the
// Python module linking the library, in a build tree moved elsewhere or installed), or where
// it was built. Null when it is nowhere or will not load; `failure` then says which places
// were tried, or why it did not load.
void* load_curdle_module(const std::string& file_name, std::string* failure);

// Where load_curdle_module would load `file_name` from, without loading it; empty when it is
// nowhere, `failure` then saying which places were tried.
std::string find_curdle_module(const std::string& file_name, std::string* failure);

}  // namespace curdle
