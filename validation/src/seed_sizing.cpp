// Seeds per state point from a smooth model of the scatter per run (see seed_sizing.hpp).
#include "molchaos/validation/seed_sizing.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "molchaos/validation/pair_correlations.hpp"

namespace molchaos::validation {
namespace {

// E ln s − ln σ for the sample standard deviation of n normal values, to second order in
// 1/(n − 1): (ψ((n−1)/2) − ln((n−1)/2))/2 with ψ(x) − ln x = −1/(2x) − 1/(12x²) + O(x⁻⁴).
double log_sd_bias(int runs) {
  const double m = runs - 1;
  return -1.0 / (2.0 * m) - 1.0 / (6.0 * m * m);
}

}  // namespace

std::vector<double> modelled_relative_scatter(const std::vector<PointScatter>& gas) {
  std::vector<double> own(gas.size(), 0.0);
  std::vector<std::size_t> used;
  for (std::size_t k = 0; k < gas.size(); ++k) {
    const auto& p = gas[k];
    if (p.runs >= 2 && p.relative_sd > 0.0 && std::isfinite(p.relative_sd)) {
      own[k] = p.relative_sd;
      used.push_back(k);
    }
  }
  if (used.size() < 2) return own;
  const int terms = used.size() >= 4 ? 3 : static_cast<int>(used.size()) - 1;
  double centre = 0.0;
  for (const auto k : used) centre += gas[k].restitution;
  centre /= static_cast<double>(used.size());
  const auto row = [&](double restitution) {
    Eigen::RowVectorXd x(terms);
    for (int j = 0; j < terms; ++j) x(j) = std::pow(restitution - centre, j);
    return x;
  };
  Eigen::MatrixXd X(used.size(), terms);
  Eigen::VectorXd y(used.size());
  for (std::size_t r = 0; r < used.size(); ++r) {
    const auto& p = gas[used[r]];
    const double weight = std::sqrt(p.runs - 1.0);
    X.row(r) = weight * row(p.restitution);
    y(r) = weight * (std::log(p.relative_sd) - log_sd_bias(p.runs));
  }
  const Eigen::VectorXd beta = X.colPivHouseholderQr().solve(y);
  std::vector<double> model(gas.size());
  for (std::size_t k = 0; k < gas.size(); ++k)
    model[k] = std::exp(row(gas[k].restitution).dot(beta));
  return model;
}

std::vector<int> seeds_needed(const std::vector<PointScatter>& gas, const SeedSizing& sizing) {
  const std::vector<double> model = modelled_relative_scatter(gas);
  const auto runs_for = [&](double relative_sd) {
    const double ratio = relative_sd / sizing.target_relative_error;
    return static_cast<int>(std::min(1e9, std::ceil(sizing.margin * ratio * ratio)));
  };
  std::vector<int> out(gas.size());
  for (std::size_t k = 0; k < gas.size(); ++k) {
    const auto& p = gas[k];
    out[k] = p.seeds;
    if (p.runs < 2) continue;  // no scatter of its own, nor a sign that more seeds would give one
    int runs = runs_for(model[k]);
    // Its own SE still above the target (a scatter the model does not follow): top it up.
    if (p.relative_sd / std::sqrt(static_cast<double>(p.runs)) > sizing.target_relative_error)
      runs = std::max(runs, runs_for(p.relative_sd));
    runs = std::max(runs, sizing.min_runs);
    // Seeds that give no A (failed runs) at the rate so far.
    const int wanted = static_cast<int>(std::ceil(static_cast<double>(runs) * p.seeds / p.runs));
    out[k] = std::max(p.seeds, std::min({sizing.max_seeds, sizing.growth * p.seeds, wanted}));
  }
  return out;
}

std::vector<double> reported_relative_scatter(const std::vector<PointScatter>& gas) {
  const std::vector<double> model = modelled_relative_scatter(gas);
  std::vector<double> out(gas.size());
  for (std::size_t k = 0; k < gas.size(); ++k) {
    const auto& p = gas[k];
    out[k] = p.relative_sd;
    if (p.runs < 2 || !(model[k] > p.relative_sd)) continue;
    // (n − 1)s²/model² is χ² with n − 1 degrees of freedom where the model holds: its lower tail
    // below 5 % rejects the model as too large.
    const int dof = p.runs - 1;
    const double ratio = p.relative_sd / model[k];
    if (1.0 - chi_square_p_value(dof * ratio * ratio, dof) >= 0.05) out[k] = model[k];
  }
  return out;
}

}  // namespace molchaos::validation
