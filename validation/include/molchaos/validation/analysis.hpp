// From runs to numbers with error bars: per-run Haff fit and contact statistics, ensemble means
// with standard errors, weighted straight-line fits, and the correlation coefficient b.
#pragma once

#include <string>
#include <vector>

#include "molchaos/sim/result.hpp"
#include "molchaos/validation/figure_data.hpp"
#include "molchaos/validation/haff_fit.hpp"
#include "molchaos/validation/hcs_window.hpp"

namespace molchaos::validation {

struct RunAnalysis {
  bool ok = false;
  std::string message;
  FitWindow window;
  HaffFit fit;
  double A = 0.0;          ///< τ0(T0 = 1)·(1 − ε²)
  double mean_dyad = 0.0;  ///< collision average of 3(c1·e)(c2·e) − c1·c2 in the window
  std::uint64_t window_collisions = 0;
  double a2 = 0.0;  ///< mean Sonine a2 over the window samples
};

RunAnalysis analyse_run(const sim::RunResult& run, const WindowRule& rule);

/// Mean and standard error of the mean (error 0 for fewer than two values).
Measurement mean_and_standard_error(const std::vector<double>& values);

/// Collision frequency per particle of an elastic run, 2·collisions/(N t), over Enskog's.
double collision_frequency_ratio(const sim::RunResult& run);

/// Weighted least-squares line y = a + b x (weights 1/σ²; unweighted if any σ is 0), by Eigen.
/// Parameter errors from the covariance, scaled by χ²/dof when χ²/dof > 1.
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
  Measurement breakdown_time;
  std::vector<std::pair<std::uint64_t, double>> A_by_seed;  ///< (seed, A) of each fitted run
  std::vector<std::string> messages;
};

/// Mean ± standard error of f(A_a, A_b) over the seeds both points have (common random numbers:
/// runs with the same seed start from the same relaxed state). Iterates a's runs in order.
template <class F>
Measurement paired_by_seed(const PointSummary& a, const PointSummary& b, F f) {
  std::vector<double> values;
  for (const auto& [seed, A] : a.A_by_seed)
    for (const auto& [seed_b, A_b] : b.A_by_seed)
      if (seed_b == seed) values.push_back(f(A, A_b));
  return mean_and_standard_error(values);
}

PointSummary summarize_point(const std::vector<const sim::RunResult*>& runs,
                             const WindowRule& rule);

}  // namespace molchaos::validation
