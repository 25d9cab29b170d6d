// A claim "y equals x" tested over all points at once: the weighted fit of y = k x with errors in
// both (the effective-variance method), and the χ² of the hypothesis k = 1. Used where two routes
// to one quantity (b from the cooling rate and b at contact) are compared over a whole grid.
#pragma once

#include <vector>

#include "molchaos/validation/figure_data.hpp"

namespace molchaos::validation {

struct ProportionalFit {
  Measurement ratio;           ///< k of y = k x, with its standard error (Δχ² = 1)
  double chi2_of_fit = 0.0;    ///< χ² at the fitted k, dof = points − 1
  double chi2_of_equal = 0.0;  ///< χ² at k = 1, dof = points
  int points = 0;              ///< pairs with a positive combined error
  double p_equal = 1.0;        ///< upper tail probability of chi2_of_equal
};

/// Fits y_i = k x_i by minimising Σ (y_i − k x_i)² / (σy_i² + k² σx_i²); points whose combined
/// error is zero are skipped. Throws std::invalid_argument when the sizes differ.
ProportionalFit fit_proportional(const std::vector<Measurement>& y,
                                 const std::vector<Measurement>& x);

}  // namespace molchaos::validation
