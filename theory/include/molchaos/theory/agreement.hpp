// The suite's one agreement rule between two numbers with errors: a measurement against kinetic
// theory, a computed coefficient against the paper's printed value, a quantity against an exact
// limit. The report's verdicts (validation/verdict.hpp) and the theory's paper checks use it.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "molchaos/theory/estimate.hpp"

namespace molchaos::theory {

/// Agreement threshold in combined standard errors (≈ 0.3 % two-sided for Gaussian errors).
inline constexpr double k_agreement_standard_errors = 3.0;

struct Agreement {
  std::optional<double> difference_in_se;  ///< (observed − expected)/σ; empty when σ = 0
  bool agrees = false;
};

/// Agreement when |observed − expected| ≤ 3σ + 1e-12·max(|observed|, |expected|), with
/// σ = √(σ_observed² + σ_expected²). The last term lets exact closed forms (σ = 0) agree with
/// their rounded double.
inline Agreement agreement(const Estimate& observed, const Estimate& expected) {
  const double sigma = std::hypot(observed.error, expected.error);
  const double difference = observed.value - expected.value;
  const double exact_slack = 1e-12 * std::max(std::abs(observed.value), std::abs(expected.value));
  Agreement a;
  if (sigma > 0.0) a.difference_in_se = difference / sigma;
  a.agrees = std::abs(difference) <= k_agreement_standard_errors * sigma + exact_slack;
  return a;
}

}  // namespace molchaos::theory
