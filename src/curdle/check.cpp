#include "curdle/check.h"

#include <cstdio>
#include <cstdlib>

namespace curdle::detail {

void check_failed(const char* file, int line, const char* condition, const std::string& values,
                  const std::string& note) {
  std::string text =
      std::string(file) + ":" + std::to_string(line) + ": check failed: " + condition;
  if (!values.empty()) text += " (" + values + ")";
  if (!note.empty()) text += ": " + note;
  std::fprintf(stderr, "%s\n", text.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace curdle::detail
