// Scatter and relative bias of the τ0 estimators on the same runs.
#include "molchaos/validation/estimator_study.hpp"

#include <cmath>
#include <map>

namespace molchaos::validation {
namespace {

std::size_t index_of(HaffEstimator e) {
  for (std::size_t i = 0; i < k_haff_estimators.size(); ++i)
    if (k_haff_estimators[i] == e) return i;
  return 0;
}

// The runs of a point where every estimator gave a value (so that all are compared alike).
std::vector<std::array<double, k_haff_estimators.size()>> complete_runs(const PointSummary& p) {
  std::vector<std::array<double, k_haff_estimators.size()>> out;
  for (const auto& run : p.A_by_estimator) {
    bool ok = true;
    for (double a : run) ok = ok && std::isfinite(a);
    if (ok) out.push_back(run);
  }
  return out;
}

}  // namespace

Measurement estimator_mean(const PointSummary& point, HaffEstimator e) {
  std::vector<double> values;
  for (const auto& run : complete_runs(point)) values.push_back(run[index_of(e)]);
  return mean_and_standard_error(values);
}

namespace {

// Values standardised to mean 0 and unit sample variance (empty if they do not vary).
std::vector<double> standardised(const std::vector<double>& v) {
  const Measurement m = mean_and_standard_error(v);
  const double sd = m.error * std::sqrt(static_cast<double>(v.size()));
  if (!(sd > 0.0)) return {};
  std::vector<double> z;
  for (double x : v) z.push_back((x - m.value) / sd);
  return z;
}

}  // namespace

Measurement seed_correlation(const std::vector<const PointSummary*>& a,
                             const std::vector<const PointSummary*>& b) {
  double sum = 0.0, dof = 0.0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    const std::map<std::uint64_t, double> in_b(b[i]->A_by_seed.begin(), b[i]->A_by_seed.end());
    std::vector<double> x, y;
    for (const auto& [seed, A] : a[i]->A_by_seed)
      if (const auto it = in_b.find(seed); it != in_b.end()) {
        x.push_back(A);
        y.push_back(it->second);
      }
    const auto zx = standardised(x), zy = standardised(y);
    if (zx.size() < 3 || zy.size() != zx.size()) continue;
    for (std::size_t k = 0; k < zx.size(); ++k) sum += zx[k] * zy[k];
    dof += static_cast<double>(zx.size()) - 1.0;
  }
  if (dof == 0.0) return {0.0, 0.0};
  return {sum / dof, 1.0 / std::sqrt(dof)};
}

std::vector<EstimatorScatter> compare_estimator_scatter(
    const std::vector<const PointSummary*>& points) {
  const std::size_t fit = index_of(HaffEstimator::least_squares);
  std::vector<std::vector<std::array<double, k_haff_estimators.size()>>> per_point;
  for (const auto* p : points) per_point.push_back(complete_runs(*p));
  std::vector<EstimatorScatter> out;
  for (std::size_t e = 0; e < k_haff_estimators.size(); ++e) {
    double weighted_variance = 0.0;
    int dof = 0;
    std::vector<double> shifts;
    for (const auto& runs : per_point) {
      if (runs.size() < 2) continue;
      std::vector<double> a;
      for (const auto& run : runs) {
        a.push_back(run[e]);
        shifts.push_back(run[e] / run[fit] - 1.0);
      }
      const Measurement m = mean_and_standard_error(a);
      const double n = static_cast<double>(a.size());
      const double relative_sd = m.error * std::sqrt(n) / m.value;  // SE·√n = sd
      weighted_variance += (n - 1.0) * relative_sd * relative_sd;
      dof += static_cast<int>(a.size()) - 1;
    }
    EstimatorScatter s;
    s.estimator = k_haff_estimators[e];
    s.degrees_of_freedom = dof;
    s.relative_sd_per_run = dof > 0 ? std::sqrt(weighted_variance / dof) : 0.0;
    s.shift_from_least_squares = mean_and_standard_error(shifts);
    out.push_back(s);
  }
  const double fit_sd = out[fit].relative_sd_per_run;
  for (auto& s : out)
    s.cost_ratio = fit_sd > 0 ? (s.relative_sd_per_run / fit_sd) * (s.relative_sd_per_run / fit_sd)
                              : 0.0;
  return out;
}

}  // namespace molchaos::validation
