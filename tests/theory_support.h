// What the theory and extinction tests share: their headers and the inline designs.
#pragma once

#include <gtest/gtest.h>

#include <cmath>

#include "curdle/boxcount.h"
#include "curdle/curdling.h"
#include "curdle/extinction.h"
#include "curdle/overlay.h"
#include "curdle/report.h"
#include "curdle/theory.h"
#include "test_support.h"

namespace curdle {

using test::design;
using test::repeat;

}  // namespace curdle
