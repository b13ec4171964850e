// What a DXF's bytes must be before they are read: an ASCII DXF (binary DXF, DWG and other
// files are named as such), of bounded size, whose entities' counts fit the file (a count that
// does not is a damaged file, named by its line).
#pragma once

#include <string>
#include <string_view>

namespace curdle::site {

// Throws InputError naming the file (and the line of a count that does not fit).
void check_dxf_bytes(std::string_view bytes, const std::string& file);

}  // namespace curdle::site
