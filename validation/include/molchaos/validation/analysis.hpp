// From runs to numbers with error bars: per-run τ0 (haff_estimators.hpp) and contact statistics, ensemble means
// with standard errors, weighted straight-line fits, and the correlation coefficient b.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "molchaos/sim/result.hpp"
#include "molchaos/validation/figure_data.hpp"
#include "molchaos/validation/haff_estimators.hpp"
#include "molchaos/validation/hcs_window.hpp"
#include "molchaos/validation/run_notes.hpp"

namespace molchaos::validation {

struct RunAnalysis {
  bool ok = false;
  std::string message;
  FitWindow window;
  Tau0Estimate tau0;  ///< by k_haff_estimator over the window
  double A = 0.0;          ///< τ0(T0 = 1)·(1 − ε²)
  double mean_dyad = 0.0;  ///< collision average of 3(c1·e)(c2·e) − c1·c2 in the window
  std::uint64_t window_collisions = 0;
  double a2 = 0.0;  ///< mean Sonine a2 over the window samples
};

RunAnalysis analyse_run(const sim::RunResult& run, const WindowRule& rule);

/// Mean and standard error of the mean (error 0 for fewer than two values).
Measurement mean_and_standard_error(const std::vector<double>& values);

/// A standard error as a table prints it: nan where fewer than two runs gave it (one run has no
/// scatter, so its error is unknown, not the 0 that mean_and_standard_error holds).
double error_of_runs(double error, int runs);

/// Collision frequency per particle of an elastic run, 2·collisions/(N t), over Enskog's, both
/// counted from the last sample at or before half the run (the start-up transient left out).
double collision_frequency_ratio(const sim::RunResult& run);

/// Weighted least-squares line y = a + b x (weights 1/σ²; unweighted if any σ is 0), by Eigen.
/// Parameter errors from the covariance, scaled by χ²/dof when χ²/dof > 1; unweighted, from the
/// residual scatter, and χ²/dof is nan (no errors, no χ²).
LinearFit fit_line(const std::vector<double>& x, const std::vector<Measurement>& y);

/// Summary of the runs of one state point.
struct PointSummary {
  int dimension = 2;
  double density = 0.0;
  double restitution = 0.0;
  std::string mode;
  int runs = 0;
  int failed = 0;
  Measurement A;  ///< ensemble mean ± standard error
  Measurement mean_dyad;
  Measurement a2;
  int breakdowns = 0;  ///< runs in which the break-down was detected
  /// t_b over those runs: mean ± the larger of the standard error and the sample grid's rounding
  /// (each t_b is the first sample past the threshold, uniform within its interval).
  Measurement breakdown_time;
  /// ln t_b over the runs that broke down, mean ± standard error (the onset on the log axis of
  /// Fig. 3; ln of the mean t_b would sit above it, t_b being skewed).
  Measurement log_breakdown_time;
  std::vector<std::pair<std::uint64_t, double>> A_by_seed;  ///< (seed, A) of each fitted run
  /// A of each fitted run by every estimator, in the order of k_haff_estimators (the
  /// estimator study compares their scatter on the same runs).
  std::vector<std::array<double, k_haff_estimators.size()>> A_by_estimator;
  std::vector<RunNote> notes;  ///< why runs gave no value (note_lines prints them grouped)
};

PointSummary summarize_point(const std::vector<const sim::RunResult*>& runs,
                             const WindowRule& rule);

}  // namespace molchaos::validation
