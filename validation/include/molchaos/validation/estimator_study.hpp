// The τ0 estimators of haff_estimators.hpp compared on the same runs: the scatter of A over
// independent runs (what a precision target costs) and the bias of each against the others and
// against an exact reference (DSMC or kinetic theory for a gas without velocity correlations).
#pragma once

#include <string>
#include <vector>

#include "molchaos/validation/analysis.hpp"
#include "molchaos/validation/haff_estimators.hpp"

namespace molchaos::validation {

struct EstimatorScatter {
  HaffEstimator estimator = HaffEstimator::least_squares;
  /// Relative standard deviation of A over runs, pooled over state points by degrees of
  /// freedom: √(Σ (n_i − 1) s_i²/Ā_i² / Σ (n_i − 1)).
  double relative_sd_per_run = 0.0;
  int degrees_of_freedom = 0;
  /// Runs needed for a given precision, relative to the least-squares fit's: (s/s_fit)².
  double cost_ratio = 0.0;
  /// A/A_fit − 1 run by run (the same runs, so the difference is paired), mean ± SE over all
  /// runs of all points: the estimator's bias relative to the least-squares fit.
  Measurement shift_from_least_squares;
};

/// Every estimator over the points' fitted runs (PointSummary::A_by_estimator).
std::vector<EstimatorScatter> compare_estimator_scatter(
    const std::vector<const PointSummary*>& points);

/// Correlation over seeds of A in two gases started from the same relaxed states (point i of
/// `a` with point i of `b`), pooled over the points: r = Σ_i Σ_seeds z_a z_b / Σ_i (n_i − 1),
/// z the values standardised within a point over the seeds both have. Its error is the null
/// hypothesis' 1/√(Σ (n_i − 1)). Near zero: pairing the gases by seed buys no precision.
Measurement seed_correlation(const std::vector<const PointSummary*>& a,
                             const std::vector<const PointSummary*>& b);

/// Mean ± standard error of A by estimator `e` over one point's fitted runs.
Measurement estimator_mean(const PointSummary& point, HaffEstimator e);

}  // namespace molchaos::validation
