// report.json: the per-stage report as JSON (schema in README.md).
#pragma once

#include <nlohmann/json.hpp>

#include "curdle/report.h"
#include "layout/layout.h"

namespace curdle {

nlohmann::ordered_json report_to_json(const Report& report);
// The same with what report.json says of the layout built from it (under "layout").
nlohmann::ordered_json report_to_json(const Report& report, const Layout& layout);

}  // namespace curdle
