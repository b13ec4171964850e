// The files a recipe names beside itself (layout.site's drawing). The recipe reader parses
// text, never files: the caller, which knows where the recipe came from and which files it may
// open, reads them through this.
#pragma once

#include <string>

#include "curdle/error.h"

namespace curdle {

class RecipeFiles {
 public:
  virtual ~RecipeFiles() = default;
  // The bytes of `name` (relative to the recipe); throws InputError at `where` when it may not
  // or cannot be read, or is larger than `max_bytes`.
  virtual std::string read(const std::string& name, const SourceLocation& where,
                           size_t max_bytes) const = 0;
};

}  // namespace curdle
