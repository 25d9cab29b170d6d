// Per-run analysis, ensemble statistics, straight-line fits.
#include "molchaos/validation/analysis.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "molchaos/sim/run.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/paper_constants.hpp"

namespace molchaos::validation {

RunAnalysis analyse_run(const sim::RunResult& run, const WindowRule& rule) {
  RunAnalysis a;
  const auto& p = run.parameters;
  a.window = choose_window(run.samples, p.particles, rule);
  if (!a.window.valid) {
    a.message = a.window.message;
    return a;
  }
  a.tau0 = estimate_tau0(k_haff_estimator, run.samples, a.window.t_start, a.window.t_stop);
  if (!a.tau0.ok) {
    a.message = a.tau0.message;
    return a;
  }
  a.A = a.tau0.tau0_unit * (1.0 - p.restitution * p.restitution);
  double dyad_sum = 0.0, a2_sum = 0.0;
  std::uint64_t count = 0;
  int a2_samples = 0;
  for (const auto& s : run.samples) {
    if (s.t < a.window.t_start || s.t > a.window.t_stop) continue;
    a2_sum += s.a2;
    ++a2_samples;
    if (s.t > a.window.t_start) {  // contact sums cover the interval ending at s.t
      dyad_sum += theory::k_paper_dyad_factor * s.contacts.sum_c1e_c2e - s.contacts.sum_c1_dot_c2;
      count += s.contacts.count;
    }
  }
  a.window_collisions = count;
  a.mean_dyad = count > 0 ? dyad_sum / static_cast<double>(count) : 0.0;
  a.a2 = a2_samples > 0 ? a2_sum / a2_samples : 0.0;
  a.ok = true;
  return a;
}

Measurement mean_and_standard_error(const std::vector<double>& values) {
  Measurement m;
  if (values.empty()) return m;
  double sum = 0.0;
  for (double v : values) sum += v;
  m.value = sum / static_cast<double>(values.size());
  if (values.size() < 2) return m;
  double ss = 0.0;
  for (double v : values) ss += (v - m.value) * (v - m.value);
  const double n = static_cast<double>(values.size());
  m.error = std::sqrt(ss / (n - 1.0) / n);
  return m;
}

double error_of_runs(double error, int runs) {
  return runs >= 2 ? error : std::numeric_limits<double>::quiet_NaN();
}

double collision_frequency_ratio(const sim::RunResult& run) {
  const auto& p = run.parameters;
  if (run.samples.empty()) return std::numeric_limits<double>::quiet_NaN();
  const sim::Sample& last = run.samples.back();
  // From the last sample at or before half the run: a shuffled gas builds up its velocity
  // correlations over its first tens of collision times (at n = 0.1 the paper's shuffle, averaged
  // from t = 0 to 200, reads 0.1 % below its steady frequency, 4 standard errors of 12 seeds).
  sim::Sample first;
  for (const auto& s : run.samples)
    if (s.t <= 0.5 * last.t) first = s;
  const double omega = 2.0 * static_cast<double>(last.collisions - first.collisions) /
                       (static_cast<double>(p.particles) * (last.t - first.t));
  return omega / theory::enskog_collision_frequency(p.dimension, p.density, last.temperature);
}

LinearFit fit_line(const std::vector<double>& x, const std::vector<Measurement>& y) {
  const auto n = static_cast<Eigen::Index>(x.size());
  if (n < 2 || y.size() != x.size())
    throw std::invalid_argument("fit_line: need at least two points and as many y as x");
  bool weighted = true;
  for (const auto& m : y) weighted = weighted && m.error > 0.0;
  Eigen::MatrixXd X(n, 2);
  Eigen::VectorXd Y(n), w(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    X(i, 0) = 1.0;
    X(i, 1) = x[i];
    Y(i) = y[i].value;
    w(i) = weighted ? 1.0 / (y[i].error * y[i].error) : 1.0;
  }
  const Eigen::MatrixXd XtW = X.transpose() * w.asDiagonal();
  const Eigen::Matrix2d normal = XtW * X;
  const Eigen::Vector2d beta = normal.ldlt().solve(XtW * Y);
  const Eigen::VectorXd r = Y - X * beta;
  const double chi2 = (r.array() * r.array() * w.array()).sum();
  const double dof = static_cast<double>(n - 2);
  Eigen::Matrix2d cov = normal.inverse();
  LinearFit f;
  const double per_dof = dof > 0 ? chi2 / dof : 0.0;  // unweighted: the mean squared residual
  // Unweighted: errors from the residual scatter, and no χ² (the points carry no errors; a
  // table or figure that printed the mean squared residual as χ²/dof would mislead).
  // Weighted: inflate only when χ²/dof > 1.
  f.chi2_per_dof = weighted ? per_dof : std::numeric_limits<double>::quiet_NaN();
  cov *= weighted ? std::max(1.0, per_dof) : per_dof;
  f.intercept = beta(0);
  f.slope = beta(1);
  f.intercept_error = std::sqrt(cov(0, 0));
  f.slope_error = std::sqrt(cov(1, 1));
  return f;
}

PointSummary summarize_point(const std::vector<const sim::RunResult*>& runs,
                             const WindowRule& rule) {
  PointSummary s;
  std::vector<double> A, dyad, a2, tb;
  double rounding = 0.0, log_rounding = 0.0;  // of the break-down times (below)
  for (const auto* r : runs) {
    const auto& p = r->parameters;
    s.dimension = p.dimension;
    s.density = p.density;
    s.restitution = p.restitution;
    s.mode = std::string(sim::to_string(p.randomize));
    const RunAnalysis a = analyse_run(*r, rule);
    if (!a.ok) {
      ++s.failed;
      s.notes.push_back({a.message, p.seed});
      continue;
    }
    ++s.runs;
    A.push_back(a.A);
    s.A_by_seed.emplace_back(p.seed, a.A);
    auto& by_estimator = s.A_by_estimator.emplace_back();
    for (std::size_t e = 0; e < k_haff_estimators.size(); ++e) {
      const Tau0Estimate t =
          estimate_tau0(k_haff_estimators[e], r->samples, a.window.t_start, a.window.t_stop);
      by_estimator[e] = t.ok ? t.tau0_unit * (1.0 - p.restitution * p.restitution)
                             : std::numeric_limits<double>::quiet_NaN();
    }
    a2.push_back(a.a2);
    if (a.window_collisions > 0) dyad.push_back(a.mean_dyad);
    if (const Breakdown& b = a.window.breakdown; b.detected) {
      ++s.breakdowns;
      tb.push_back(b.time);
      // Each time is known to within its sample interval (uniform: variance width²/12).
      rounding += (b.time - b.previous) * (b.time - b.previous) / 12.0;
      if (b.previous > 0) log_rounding += std::pow(std::log(b.time / b.previous), 2) / 12.0;
    }
  }
  s.A = mean_and_standard_error(A);
  s.mean_dyad = mean_and_standard_error(dyad);
  s.a2 = mean_and_standard_error(a2);
  s.breakdown_time = mean_and_standard_error(tb);
  std::vector<double> ln_tb;
  for (double t : tb) ln_tb.push_back(std::log(t));
  s.log_breakdown_time = mean_and_standard_error(ln_tb);
  // Runs that broke down at the same sample scatter by nothing: their mean is still only known to
  // the rounding of the sample grid, which floors its error (as the larger of the two).
  if (s.breakdowns > 0) {
    const double k = s.breakdowns;
    s.breakdown_time.error = std::max(s.breakdown_time.error, std::sqrt(rounding) / k);
    s.log_breakdown_time.error = std::max(s.log_breakdown_time.error, std::sqrt(log_rounding) / k);
  }
  if (s.runs == 0) {  // nothing measured: not a value of 0 (tables print nan, runs = 0)
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.A = s.mean_dyad = s.a2 = Measurement{nan, nan};
  }
  return s;
}

}  // namespace molchaos::validation
