// Shared by the break-down tests: the rows of the linear regime (growth rates, stationary levels)
// agree with linear hydrodynamics within 3 of their jackknife standard errors.
#pragma once

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "molchaos/validation/breakdown.hpp"

/// Checks every linear-regime row; returns how many it checked.
inline int check_linear_rows(const std::vector<molchaos::validation::BreakdownRow>& rows) {
  int asserted = 0;
  for (const auto& r : rows) {
    if (!r.linear_regime) continue;
    BOOST_TEST_REQUIRE(std::isfinite(r.measured_error), r.quantity);
    BOOST_TEST(
        std::abs(r.measured - r.predicted) <= 3 * r.measured_error,
        r.quantity << ": " << r.measured << " ± " << r.measured_error << " vs " << r.predicted);
    ++asserted;
  }
  return asserted;
}
