// The report as a readable text table, for `curdle report` and the end of `curdle generate`.
#pragma once

#include <string>

#include "curdle/report.h"

namespace curdle {

std::string format_report_table(const Report& report);

}  // namespace curdle
