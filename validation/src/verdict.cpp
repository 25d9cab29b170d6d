// The one verdict rule (see verdict.hpp).
#include "molchaos/validation/verdict.hpp"

#include <fmt/format.h>

#include "molchaos/validation/pair_correlations.hpp"

namespace molchaos::validation {

bool significantly_below(const Measurement& observed, double bound) {
  return observed.value + k_agreement_standard_errors * observed.error < bound;
}

void GlobalTest::add(double difference_in_se, int runs) {
  const double z = normal_score(difference_in_se, runs - 1);
  chi2 += z * z;
  ++points;
}

double GlobalTest::p() const { return chi_square_p_value(chi2, points); }

std::string agreement_rule_text() {
  return fmt::format("equal within {:g} combined SE", k_agreement_standard_errors);
}

std::string bound_rule_text(double bound) {
  return fmt::format("value + {:g} SE below {:g}", k_agreement_standard_errors, bound);
}

}  // namespace molchaos::validation
