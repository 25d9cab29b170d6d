// The theory report (theory_report.hpp) as one JSON document: what `molchaos theory --json`
// prints and what the Python module's theory() returns, key for key. Numbers that are not finite
// (τ0 where the gas does not cool, an open end of the b range) are null.
#pragma once

#include <nlohmann/json.hpp>

#include "molchaos/theory/theory_report.hpp"

namespace molchaos::theory {

/// The document of the report r of the inputs `in`; `version` is the suite's version string.
nlohmann::json report_json(const ReportInputs& in, const TheoryReport& r, const char* version);

}  // namespace molchaos::theory
