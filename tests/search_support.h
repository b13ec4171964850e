// The two-curd field the seed search and segment measure tests share.
#pragma once

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <functional>
#include <random>

#include "curdle/boxcount.h"
#include "curdle/curdling.h"
#include "curdle/error.h"
#include "curdle/overlay.h"
#include "curdle/report.h"
#include "curdle/search.h"
#include "curdle/segment_measures.h"
#include "test_support.h"

namespace curdle {

inline Design two_curds_128() {
  Design d = test::design(2, 2,
                          {{"0.8", "0.8", "0.7", "0.7", "0.7", "0.7", "0.7"},
                           {"0.9", "0.6", "0.8", "0.7", "0.8", "0.7", "0.8"}});
  d.field.size = {200, 150, 1};  // two by two roots, cropped
  return d;
}

inline Box box(int64_t x, int64_t y, int64_t w, int64_t h) {
  Box b;
  b.origin = {x, y, 0};
  b.size = {w, h, 1};
  return b;
}

}  // namespace curdle
