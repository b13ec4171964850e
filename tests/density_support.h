// The radial density design the density tests share.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/run.h"
#include "curdle/boxcount.h"
#include "curdle/curdling.h"
#include "curdle/density.h"
#include "curdle/error.h"
#include "curdle/report.h"
#include "io/image.h"
#include "layout/builder.h"
#include "layout/cell_placement.h"
#include "recipe/recipe.h"
#include "test_support.h"

namespace curdle {

// One 64 x 64 root (base 4, 3 stages), P_K = 1/3, thickening toward the middle: 0.9 at the
// centre, 0.05 from 32 cells out.
inline Design radial_design() {
  Design d = test::design(4, 2, {{"3/4", "2/3", "2/3"}});
  DensityField f;
  f.kind = DensityKind::radial;
  f.centre = {32, 32, 0};
  f.radius = 32;
  f.values = {2.7, 0.15};
  d.curds[0].density = f;
  return d;
}

inline double distance_from_centre(int64_t x, int64_t y) {
  return std::hypot(static_cast<double>(x) + 0.5 - 32, static_cast<double>(y) + 0.5 - 32);
}

}  // namespace curdle
