// The suite's one verdict rule: when a measured or computed number agrees with the value it is
// compared with (kinetic theory, the paper's printed value, an exact limit), and when it lies
// below a stated bound. Every verdict of the report comes from these two functions.
#pragma once

#include <optional>
#include <string>

#include "molchaos/validation/figure_data.hpp"

namespace molchaos::validation {

/// Agreement threshold in combined standard errors (≈ 0.3 % two-sided for Gaussian errors).
inline constexpr double k_agreement_standard_errors = 3.0;

struct Agreement {
  std::optional<double> difference_in_se;  ///< (observed − expected)/σ; empty when σ = 0
  bool agrees = false;
};

/// Agreement when |observed − expected| ≤ 3σ + 1e-12·max(|observed|, |expected|), with
/// σ = √(σ_observed² + σ_expected²). The last term lets exact closed forms (σ = 0) agree with
/// their rounded double.
Agreement agreement(const Measurement& observed, const Measurement& expected);

/// True when observed + 3σ_observed < bound (a claim of the form "less than bound").
bool significantly_below(const Measurement& observed, double bound);

/// The rule as the report states it.
std::string agreement_rule_text();
std::string bound_rule_text(double bound);

}  // namespace molchaos::validation
