#include "curdle/chi_square.h"

#include <algorithm>
#include <cmath>

namespace curdle {
namespace {

// Q(a, x) = Gamma(a, x) / Gamma(a): by the series of P(a, x) below x = a + 1, where it
// converges fast, and by Lentz's continued fraction above it.
double upper_gamma(double a, double x) {
  if (x <= 0) return 1.0;
  const double log_front = a * std::log(x) - x - std::lgamma(a);
  if (x < a + 1) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 10000 && std::fabs(term) > std::fabs(sum) * 1e-16; ++n) {
      term *= x / (a + n);
      sum += term;
    }
    return std::max(0.0, 1.0 - sum * std::exp(log_front));
  }
  constexpr double tiny = 1e-300;
  double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
  for (int n = 1; n < 10000; ++n) {
    const double an = -n * (n - a);
    b += 2;
    d = an * d + b;
    d = std::fabs(d) < tiny ? tiny : d;
    c = b + an / c;
    c = std::fabs(c) < tiny ? tiny : c;
    d = 1 / d;
    const double step = d * c;
    h *= step;
    if (std::fabs(step - 1) < 1e-16) break;
  }
  return std::exp(log_front) * h;
}

}  // namespace

double chi_square_tail(double statistic, double degrees) {
  if (!(degrees > 0)) return 1.0;
  return upper_gamma(degrees / 2, statistic / 2);
}

}  // namespace curdle
