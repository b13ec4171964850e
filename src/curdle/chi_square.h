// Pearson's chi-square test: how likely a statistic this large is when the model holds.
#pragma once

namespace curdle {

// P(X >= statistic) for X chi-square with `degrees` degrees of freedom (> 0): the upper
// regularised incomplete gamma Q(degrees / 2, statistic / 2).
double chi_square_tail(double statistic, double degrees);

}  // namespace curdle
