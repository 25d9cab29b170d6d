// The error of a straight-line fit through ensemble means whose runs share seeds. The runs of one
// seed at every ε of a Fig. 4 series start from the same relaxed state, so the point means are
// not independent, and the fit's error (which assumes they are) may be too small or too large.
#pragma once

#include <optional>
#include <vector>

#include "molchaos/validation/analysis.hpp"

namespace molchaos::validation {

/// The slope of the weighted fit (weights 1/SE², as fit_line) is a fixed linear combination
/// Σ_a c_a ȳ_a of the point means. Its error by the jackknife over seeds: leaving seed s out of
/// every point that ran it moves the slope by d_s = −Σ_{a ∋ s} c_a (A_as − ȳ_a) / (n_a − 1), and
/// the variance is (G − 1)/G Σ_s (d_s − d̄)² over the G seeds, whatever the correlation between
/// the points. With no seed shared it is (G − 1)/G Σ_a c_a² SE_a² n_a/(n_a − 1), fit_line's
/// variance before its χ² scaling up to those factors. Returns the standard error, or nothing
/// where a point has fewer than two runs or no scatter (PointSummary::A_by_seed, A.error).
std::optional<double> slope_error_over_shared_seeds(const std::vector<double>& x,
                                                    const std::vector<const PointSummary*>& points);

}  // namespace molchaos::validation
