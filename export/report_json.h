// report.json: the per-stage report as JSON (schema in README.md).
#pragma once

#include <nlohmann/json.hpp>

#include "curdle/report.h"

namespace curdle {

nlohmann::ordered_json report_to_json(const Report& report);

}  // namespace curdle
