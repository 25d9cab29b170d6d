// The correction of a staged point's SE for optional stopping (validation/stopping_correction.hpp),
// tested on simulated gases of known scatter, staged by this file's own simulation of the sizing:
// at every point the corrected error bars must match the true spread of the means, where the
// uncorrected ones are short at the points that grow most.
#define BOOST_TEST_MODULE validation_stopping_correction
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

#include "molchaos/validation/stopping_correction.hpp"

using namespace molchaos::validation;

namespace {

struct Gas {
  std::vector<double> restitution, sigma;  // relative scatter of A per run
  int first_seeds = 0;
  double target = 0.0;
};

// Three restitutions as `sweep --restitution 0.8,0.9,0.95 --seeds 4 --target-error 0.003` of 1000
// disks at n = 0.05 (whose mean run counts, 50, 20 and 13, these scatters give); and ten from 1 %
// to 0.3 % as the reproduction's gases (8 seeds, target 0.15 %).
Gas three_points() { return {{0.8, 0.9, 0.95}, {0.019, 0.0117, 0.0095}, 4, 0.003}; }
Gas ten_points() {
  Gas g{{}, {}, 8, 0.0015};
  for (int k = 0; k < 10; ++k) {
    g.restitution.push_back(0.80 + 0.02 * k);
    g.sigma.push_back(0.010 - 0.007 * k / 9.0);
  }
  return g;
}

struct StagedPoint {
  int runs = 0;
  double relative_sd = 0.0;
};
struct StagedGas {
  std::vector<StagedPoint> points;
  Staging staging;  // with the factors of its last sizing
};

constexpr int k_stages = 5;  // as the staging of sweep and reproduce (staged_ensemble.hpp)

// One staged gas: first_seeds normal runs a point, then up to k_stages stages sized as
// grow_to_target sizes them: seeds_needed for the scatters times the factors found at that stage
// (with fewer replicas than the default, for speed).
StagedGas stage(const Gas& g, Staging staging, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  const std::size_t m = g.sigma.size();
  std::vector<std::vector<double>> runs(m);
  const auto add = [&](std::size_t k, int count) {
    for (int i = 0; i < count; ++i) runs[k].push_back(1.0 + g.sigma[k] * normal(rng));
  };
  const auto summary = [&] {
    std::vector<PointScatter> gas;
    for (std::size_t k = 0; k < m; ++k) {
      const int n = static_cast<int>(runs[k].size());
      double mean = 0.0, ss = 0.0;
      for (const double x : runs[k]) mean += x / n;
      for (const double x : runs[k]) ss += (x - mean) * (x - mean);
      gas.push_back({g.restitution[k], n, n, std::sqrt(ss / (n - 1)) / mean});
    }
    return gas;
  };
  for (std::size_t k = 0; k < m; ++k) add(k, g.first_seeds);
  for (int s = 0; s < staging.stages; ++s) {
    const auto gas = summary();
    staging.sizing_factors = stopping_correction(gas, reported_relative_scatter(gas), staging,
                                                 {100, 11u + static_cast<unsigned>(rng() >> 40)});
    const auto needed = seeds_needed_for_factors(gas, staging.sizing_factors, staging.sizing);
    bool grown = false;
    for (std::size_t k = 0; k < m; ++k)
      if (needed[k] > gas[k].seeds) {
        add(k, needed[k] - gas[k].seeds);
        grown = true;
      }
    if (!grown) break;
  }
  StagedGas out{{}, staging};
  for (const auto& p : summary()) out.points.push_back({p.runs, p.relative_sd});
  return out;
}

// Per point, the true spread of the means over the rms reported SE, σ √E[1/n] / √E[r²/n], with
// the reported scatter r as it is and corrected, and the error of each ratio over the K gases.
struct Coverage {
  std::vector<double> reported, corrected, reported_err, corrected_err;
};
Coverage coverage(const Gas& g, int gases, int replicas) {
  SeedSizing sizing;
  sizing.target_relative_error = g.target;
  const Staging staging{std::vector<int>(g.sigma.size(), g.first_seeds), sizing, k_stages, {}};
  std::mt19937_64 rng(20261125);
  const std::size_t m = g.sigma.size();
  std::vector<double> inv(m), r2(m), r4(m), c2(m), c4(m);
  for (int i = 0; i < gases; ++i) {
    const StagedGas staged = stage(g, staging, rng);
    const auto& points = staged.points;
    std::vector<PointScatter> gas;
    for (std::size_t k = 0; k < m; ++k)
      gas.push_back({g.restitution[k], points[k].runs, points[k].runs, points[k].relative_sd});
    const auto r = reported_relative_scatter(gas);
    const auto c =
        stopping_correction(gas, r, staged.staging, {replicas, 7u + static_cast<unsigned>(i)});
    for (std::size_t k = 0; k < m; ++k) {
      const double n = points[k].runs, v = r[k] * r[k] / n, w = v * c[k] * c[k];
      inv[k] += 1.0 / n;
      r2[k] += v;
      r4[k] += v * v;
      c2[k] += w;
      c4[k] += w * w;
    }
  }
  Coverage out;
  for (std::size_t k = 0; k < m; ++k) {
    const double truth = g.sigma[k] * std::sqrt(inv[k] / gases);
    const auto ratio = [&](double s1, double s2, std::vector<double>& value,
                           std::vector<double>& error) {
      const double mean = s1 / gases, sd = std::sqrt(s2 / gases - mean * mean);
      value.push_back(truth / std::sqrt(mean));
      error.push_back(0.5 * value.back() * sd / mean / std::sqrt(gases));  // δ√x = δx / (2√x)
    };
    ratio(r2[k], r4[k], out.reported, out.reported_err);
    ratio(c2[k], c4[k], out.corrected, out.corrected_err);
  }
  return out;
}

}  // namespace

// Over 600 simulated gases each, the uncorrected bars are 3 % short at the most-grown point of the
// three-point gas and 7 % long at the ten-point gas's last point, which stays at min_runs and
// reports the larger model. The correction takes its simulated truth from the reported scatter
// itself, so it cannot see where the smooth model misses the true scatter, and a residual of a few
// per cent stays there (4 % long at 0.98 here). The corrected bars must lie within 4 % of the true
// spread at every point (beyond the ratios' own error, up to 1 %) and closer to it over each gas
// than the uncorrected ones, in rms (measured: 0.009 against 0.023, and 0.015 against 0.024).
BOOST_AUTO_TEST_CASE(corrected_error_bars_match_the_spread_of_staged_means) {
  for (const auto& g : {three_points(), ten_points()}) {
    const Coverage q = coverage(g, 600, 400);
    const std::size_t m = g.sigma.size();
    double reported_ms = 0.0, corrected_ms = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
      BOOST_TEST_MESSAGE("ε = " << g.restitution[k] << ": true SE / rms SE " << q.reported[k]
                                << " ± " << q.reported_err[k] << " as reported, " << q.corrected[k]
                                << " ± " << q.corrected_err[k] << " corrected");
      BOOST_TEST(std::abs(q.corrected[k] - 1.0) < 0.04 + 3.0 * q.corrected_err[k]);
      reported_ms += std::pow(q.reported[k] - 1.0, 2) / static_cast<double>(m);
      corrected_ms += std::pow(q.corrected[k] - 1.0, 2) / static_cast<double>(m);
    }
    BOOST_TEST_MESSAGE("rms deviation from 1: " << std::sqrt(reported_ms) << " as reported, "
                                                << std::sqrt(corrected_ms) << " corrected");
    BOOST_TEST(corrected_ms < reported_ms);
  }
}

// The factors are a Monte Carlo estimate: with the default 2000 replicas their scatter over the
// generator's seed is below 1 % (the header's figure), and one seed gives the same factors twice.
BOOST_AUTO_TEST_CASE(factors_are_reproducible_and_precise) {
  const Gas g = three_points();
  SeedSizing sizing;
  sizing.target_relative_error = g.target;
  const Staging staging{{4, 4, 4}, sizing, k_stages, {}};
  // A gas as a staging leaves it: 50, 20 and 13 runs (one failed seed at 0.9), scatter near σ.
  const std::vector<PointScatter> gas{
      {0.8, 50, 50, 0.0185}, {0.9, 21, 20, 0.0121}, {0.95, 13, 13, 0.0090}};
  const auto reported = reported_relative_scatter(gas);
  BOOST_TEST(
      stopping_correction(gas, reported, staging) == stopping_correction(gas, reported, staging),
      boost::test_tools::per_element());
  std::vector<double> sum(3), sum2(3);
  constexpr int seeds = 12;
  for (int s = 0; s < seeds; ++s) {
    const auto c = stopping_correction(gas, reported, staging, {2000, 100u + s});
    for (std::size_t k = 0; k < 3; ++k) {
      sum[k] += c[k];
      sum2[k] += c[k] * c[k];
    }
  }
  for (std::size_t k = 0; k < 3; ++k) {
    const double mean = sum[k] / seeds;
    const double sd = std::sqrt((sum2[k] / seeds - mean * mean) * seeds / (seeds - 1));
    BOOST_TEST_MESSAGE("ε = " << gas[k].restitution << ": factor " << mean << ", sd over seeds "
                              << sd);
    BOOST_TEST(sd < 0.01);
  }
}
