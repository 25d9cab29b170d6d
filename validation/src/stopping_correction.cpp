// Optional stopping's bias on a staged point's SE, by re-running its staging (see
// stopping_correction.hpp).
#include "molchaos/validation/stopping_correction.hpp"

#include <cmath>
#include <stdexcept>

#include "molchaos/sim/rng.hpp"

namespace molchaos::validation {
namespace {

// One simulated point: its seeds so far and the running mean and sum of squared deviations of its
// runs (Welford), each run 1 + σ z.
struct SimulatedPoint {
  int seeds = 0;
  int runs = 0;
  double mean = 0.0;
  double squares = 0.0;

  void add_seeds(int count, double sigma, double failure_rate, sim::Rng& rng) {
    for (int i = 0; i < count; ++i) {
      ++seeds;
      if (rng.uniform() < failure_rate) continue;
      const double x = 1.0 + sigma * rng.normal();
      ++runs;
      const double delta = x - mean;
      mean += delta / runs;
      squares += delta * (x - mean);
    }
  }
  double relative_sd() const { return runs >= 2 ? std::sqrt(squares / (runs - 1)) / mean : 0.0; }
};

std::vector<PointScatter> scatter_of(const std::vector<PointScatter>& gas,
                                     const std::vector<SimulatedPoint>& points) {
  std::vector<PointScatter> out;
  for (std::size_t k = 0; k < gas.size(); ++k)
    out.push_back({gas[k].restitution, points[k].seeds, points[k].runs, points[k].relative_sd()});
  return out;
}

}  // namespace

std::vector<double> stopping_correction(const std::vector<PointScatter>& gas,
                                        const std::vector<double>& reported, const Staging& staging,
                                        const StoppingCorrectionOptions& options) {
  const std::size_t m = gas.size();
  if (reported.size() != m || staging.first_seeds.size() != m ||
      !(staging.sizing_factors.empty() || staging.sizing_factors.size() == m))
    throw std::invalid_argument(
        "stopping_correction: needs one reported scatter, first seed count and sizing factor (if "
        "any) per point");
  std::vector<double> failure_rate(m, 1.0);
  for (std::size_t k = 0; k < m; ++k)
    if (gas[k].runs >= 2 && reported[k] > 0.0)
      failure_rate[k] = 1.0 - static_cast<double>(gas[k].runs) / gas[k].seeds;

  sim::Rng rng(options.seed);
  std::vector<double> sum_inverse_runs(m, 0.0), sum_reported_variance(m, 0.0);
  for (int replica = 0; replica < options.replicas; ++replica) {
    std::vector<SimulatedPoint> points(m);
    for (std::size_t k = 0; k < m; ++k)
      points[k].add_seeds(staging.first_seeds[k], reported[k], failure_rate[k], rng);
    for (int stage = 0; stage < staging.stages; ++stage) {
      const std::vector<int> needed =
          seeds_needed_for_factors(scatter_of(gas, points), staging.sizing_factors, staging.sizing);
      bool grown = false;
      for (std::size_t k = 0; k < m; ++k)
        if (needed[k] > points[k].seeds) {
          points[k].add_seeds(needed[k] - points[k].seeds, reported[k], failure_rate[k], rng);
          grown = true;
        }
      if (!grown) break;
    }
    const std::vector<double> r = reported_relative_scatter(scatter_of(gas, points));
    for (std::size_t k = 0; k < m; ++k) {
      if (points[k].runs < 2) continue;
      const double n = points[k].runs;
      sum_inverse_runs[k] += 1.0 / n;
      sum_reported_variance[k] += r[k] * r[k] / n;
    }
  }
  std::vector<double> factor(m, 1.0);
  for (std::size_t k = 0; k < m; ++k)
    if (failure_rate[k] < 1.0 && sum_reported_variance[k] > 0.0)
      factor[k] = reported[k] * std::sqrt(sum_inverse_runs[k] / sum_reported_variance[k]);
  return factor;
}

std::vector<int> seeds_needed_for_factors(const std::vector<PointScatter>& gas,
                                          const std::vector<double>& factors,
                                          const SeedSizing& sizing) {
  if (factors.empty()) return seeds_needed(gas, sizing);
  std::vector<PointScatter> scaled = gas;
  for (std::size_t k = 0; k < gas.size(); ++k) scaled[k].relative_sd *= factors.at(k);
  return seeds_needed(scaled, sizing);
}

}  // namespace molchaos::validation
