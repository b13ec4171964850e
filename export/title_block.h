// What a drawing's title block says about where the layout came from.
#pragma once

#include <cstdint>
#include <string>

namespace curdle {

struct TitleBlock {
  std::string recipe;
  std::string description;
  uint64_t seed = 0;
};

}  // namespace curdle
