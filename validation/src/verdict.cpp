// The one verdict rule (see verdict.hpp).
#include "molchaos/validation/verdict.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace molchaos::validation {

Agreement agreement(const Measurement& observed, const Measurement& expected) {
  const double sigma = std::hypot(observed.error, expected.error);
  const double difference = observed.value - expected.value;
  const double exact_slack = 1e-12 * std::max(std::abs(observed.value), std::abs(expected.value));
  Agreement a;
  if (sigma > 0.0) a.difference_in_se = difference / sigma;
  a.agrees = std::abs(difference) <= k_agreement_standard_errors * sigma + exact_slack;
  return a;
}

bool significantly_below(const Measurement& observed, double bound) {
  return observed.value + k_agreement_standard_errors * observed.error < bound;
}

std::string agreement_rule_text() {
  return fmt::format("agrees within {:g} combined SE", k_agreement_standard_errors);
}

std::string bound_rule_text(double bound) {
  return fmt::format("value + {:g} SE below {:g}", k_agreement_standard_errors, bound);
}

}  // namespace molchaos::validation
