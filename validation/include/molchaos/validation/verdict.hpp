// The suite's one verdict rule: when a measured or computed number agrees with the value it is
// compared with (kinetic theory, the paper's printed value, an exact limit: the theory library's
// agreement()), and when it lies below a stated bound. Every verdict of the report comes from
// these two functions.
#pragma once

#include <optional>
#include <string>

#include "molchaos/theory/agreement.hpp"
#include "molchaos/validation/figure_data.hpp"

namespace molchaos::validation {

using theory::Agreement;
using theory::agreement;
using theory::k_agreement_standard_errors;

/// A claim over many points (a χ² over all of them) holds when its upper tail probability is at
/// least that of a single number at 3 standard errors, two-sided: p = 0.0027.
inline constexpr double k_global_p_threshold = 0.0027;

/// Such a χ², point by point: a difference of `difference_in_se` standard errors of a mean over
/// `runs` runs (Student's t with runs − 1 degrees of freedom) enters as the normal score of the
/// same tail probability, squared.
struct GlobalTest {
  double chi2 = 0.0;
  int points = 0;
  void add(double difference_in_se, int runs);
  /// Upper tail probability of chi2 for `points` degrees of freedom.
  double p() const;
  bool holds() const { return points > 0 && p() >= k_global_p_threshold; }
  double chi2_per_dof() const { return points > 0 ? chi2 / points : 0.0; }
};

/// True when observed + 3σ_observed < bound (a claim of the form "less than bound").
bool significantly_below(const Measurement& observed, double bound);

/// The rule as the report states it.
std::string agreement_rule_text();
std::string bound_rule_text(double bound);

}  // namespace molchaos::validation
