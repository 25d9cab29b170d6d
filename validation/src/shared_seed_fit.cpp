// The jackknife-over-seeds error of a straight-line fit (shared_seed_fit.hpp).
#include "molchaos/validation/shared_seed_fit.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <map>
#include <stdexcept>

namespace molchaos::validation {

std::optional<double> slope_error_over_shared_seeds(
    const std::vector<double>& x, const std::vector<const PointSummary*>& points) {
  const auto n = static_cast<Eigen::Index>(x.size());
  if (n < 2 || points.size() != x.size())
    throw std::invalid_argument(
        "slope_error_over_shared_seeds: need at least two points and "
        "as many points as x");
  // The slope's coefficients c = row 1 of (Xᵀ W X)⁻¹ Xᵀ W.
  Eigen::MatrixXd X(n, 2);
  Eigen::VectorXd w(n);
  for (Eigen::Index a = 0; a < n; ++a) {
    const PointSummary& p = *points[static_cast<std::size_t>(a)];
    if (p.A_by_seed.size() < 2 || !(p.A.error > 0.0)) return std::nullopt;
    X(a, 0) = 1.0;
    X(a, 1) = x[static_cast<std::size_t>(a)];
    w(a) = 1.0 / (p.A.error * p.A.error);
  }
  const Eigen::MatrixXd XtW = X.transpose() * w.asDiagonal();
  const Eigen::RowVectorXd c = (XtW * X).inverse().row(1) * XtW;
  // Leaving seed s out moves the slope by d_s = −Σ_{a ∋ s} c_a (A_as − ȳ_a) / (n_a − 1).
  std::map<std::uint64_t, double> d;
  for (Eigen::Index a = 0; a < n; ++a) {
    const PointSummary& p = *points[static_cast<std::size_t>(a)];
    const double runs = static_cast<double>(p.A_by_seed.size());
    for (const auto& [seed, A] : p.A_by_seed) d[seed] -= c(a) * (A - p.A.value) / (runs - 1.0);
  }
  const double seeds = static_cast<double>(d.size());
  double mean = 0.0, spread = 0.0;
  for (const auto& [seed, shift] : d) mean += shift / seeds;
  for (const auto& [seed, shift] : d) spread += (shift - mean) * (shift - mean);
  return std::sqrt((seeds - 1.0) / seeds * spread);
}

}  // namespace molchaos::validation
