// The jackknife-over-seeds slope error of a Fig. 4 line fit (validation/shared_seed_fit.hpp): its
// closed form when no seed is shared, exact for a seed effect tilted in ε, and, on simulated
// ensembles whose points share seeds, close to the true scatter of the slope where the fit's own
// error is not.
#define BOOST_TEST_MODULE validation_shared_seed_fit
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

#include "molchaos/validation/shared_seed_fit.hpp"

using namespace molchaos::validation;

namespace {

const std::vector<double> k_x{0.80, 0.82, 0.84, 0.86, 0.88, 0.90, 0.92, 0.94, 0.96, 0.98};

// A point from its runs' values; seeds first_seed, first_seed + 1, ...
PointSummary point(const std::vector<double>& values, std::uint64_t first_seed) {
  PointSummary p;
  for (std::size_t k = 0; k < values.size(); ++k)
    p.A_by_seed.emplace_back(first_seed + k, values[k]);
  p.runs = static_cast<int>(values.size());
  p.A = mean_and_standard_error(values);
  return p;
}

std::vector<const PointSummary*> pointers(const std::vector<PointSummary>& points) {
  std::vector<const PointSummary*> out;
  for (const auto& p : points) out.push_back(&p);
  return out;
}

// The fit's own slope error without its χ² scaling.
double independent_slope_error(const std::vector<PointSummary>& points) {
  std::vector<Measurement> y;
  for (const auto& p : points) y.push_back(p.A);
  const LinearFit f = fit_line(k_x, y);
  return f.slope_error / std::sqrt(std::max(1.0, f.chi2_per_dof));
}

}  // namespace

BOOST_AUTO_TEST_CASE(no_shared_seed_gives_the_closed_form) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal;
  std::vector<PointSummary> points;
  double seeds = 0.0;
  for (std::size_t a = 0; a < k_x.size(); ++a) {
    std::vector<double> v(8 + 5 * a);
    for (double& x : v) x = 1.0 + 0.01 * (1.0 + static_cast<double>(a)) * normal(rng);
    points.push_back(point(v, 1000 * a));  // seeds apart
    seeds += static_cast<double>(v.size());
  }
  // (G − 1)/G Σ c_a² SE_a² n_a/(n_a − 1), c_a the weighted slope's coefficients.
  double sw = 0.0, swx = 0.0, swxx = 0.0;
  for (std::size_t a = 0; a < k_x.size(); ++a) {
    const double w = 1.0 / (points[a].A.error * points[a].A.error);
    sw += w;
    swx += w * k_x[a];
    swxx += w * k_x[a] * k_x[a];
  }
  double variance = 0.0;
  for (std::size_t a = 0; a < k_x.size(); ++a) {
    const double w = 1.0 / (points[a].A.error * points[a].A.error);
    const double c = w * (sw * k_x[a] - swx) / (sw * swxx - swx * swx);
    const double n = points[a].runs;
    variance += c * c * points[a].A.error * points[a].A.error * n / (n - 1.0);
  }
  variance *= (seeds - 1.0) / seeds;
  BOOST_TEST(*slope_error_over_shared_seeds(k_x, pointers(points)) == std::sqrt(variance),
             boost::test_tools::tolerance(1e-12));
  // A point of one run has no scatter: no error is given.
  std::vector<PointSummary> short_of_runs = points;
  short_of_runs[3] = point({1.0}, 3000);
  BOOST_TEST(!slope_error_over_shared_seeds(k_x, pointers(short_of_runs)).has_value());
  // and within a few per cent of the fit's own error
  BOOST_TEST(
      *slope_error_over_shared_seeds(k_x, pointers(points)) / independent_slope_error(points) ==
          1.0,
      boost::test_tools::tolerance(0.05));
}

// A_as = μ_a + δ_s x_a, the same seeds at every point: the slope of the means is slope(μ) + δ̄,
// so its variance is the sample variance of δ over the seeds divided by their number, exactly.
BOOST_AUTO_TEST_CASE(a_tilted_seed_effect_is_exact) {
  const std::vector<double> delta{0.3, -1.2, 0.7, 0.05, -0.4, 1.1, -0.2, 0.6, -0.9};
  const double n = static_cast<double>(delta.size());
  double mean = 0.0, var = 0.0;
  for (double d : delta) mean += d / n;
  for (double d : delta) var += (d - mean) * (d - mean) / (n - 1.0);
  std::vector<PointSummary> points;
  for (std::size_t a = 0; a < k_x.size(); ++a) {
    std::vector<double> v;
    // a small point-own part, so that every point has an SE; the tilt dominates
    for (std::size_t s = 0; s < delta.size(); ++s)
      v.push_back(2.0 + 0.1 * static_cast<double>(a) + delta[s] * k_x[a] +
                  1e-9 * static_cast<double>((s * 7 + a * 3) % 5));
    points.push_back(point(v, 1));
  }
  const double expected = std::sqrt(var / n);
  BOOST_TEST(*slope_error_over_shared_seeds(k_x, pointers(points)) == expected,
             boost::test_tools::tolerance(1e-6));
  // A common offset per seed (no tilt) does not move the slope at all.
  std::vector<PointSummary> offset;
  for (std::size_t a = 0; a < k_x.size(); ++a) {
    std::vector<double> v;
    for (std::size_t s = 0; s < delta.size(); ++s)
      v.push_back(2.0 + 0.1 * static_cast<double>(a) + delta[s]);
    offset.push_back(point(v, 1));
  }
  BOOST_TEST(*slope_error_over_shared_seeds(k_x, pointers(offset)) < 1e-12);
  BOOST_TEST(independent_slope_error(offset) > 0.1);
}

// Ensembles as reproduce runs them: seeds 1..n_a at point a (nested, 8 to 40 runs), each run's A
// = 1 + its seed's effect at that ε + its own noise, the seed's effect correlated between nearby ε
// (r = 0.8 between neighbours, falling geometrically) or a common offset. Over 4000 ensembles the
// jackknife errors' root mean square must match the slopes' true scatter; the fit's own error
// does not for the correlated effect (the nested seeds leave it about right for the offset).
BOOST_AUTO_TEST_CASE(on_simulated_ensembles_the_jackknife_error_is_near_the_true_scatter) {
  const std::vector<int> runs{40, 32, 24, 16, 12, 8, 8, 10, 14, 20};
  struct Case {
    const char* name;
    double rho, offset;  // neighbour correlation of the seed effect; common offset's sd
  };
  for (const Case c : {Case{"correlated in ε", 0.8, 0.0}, Case{"common offset", 0.0, 0.02}}) {
    std::mt19937_64 rng(11);
    std::normal_distribution<double> normal;
    const int ensembles = 4000;
    double sum = 0.0, sum2 = 0.0, jackknife2 = 0.0, independent2 = 0.0;
    for (int e = 0; e < ensembles; ++e) {
      const int seeds = *std::max_element(runs.begin(), runs.end());
      std::vector<std::vector<double>> effect(seeds, std::vector<double>(k_x.size()));
      for (auto& f : effect) {
        const double common = c.offset * normal(rng);
        double ar = normal(rng);
        for (std::size_t a = 0; a < k_x.size(); ++a) {
          if (a > 0) ar = c.rho * ar + std::sqrt(1.0 - c.rho * c.rho) * normal(rng);
          f[a] = common + (c.rho > 0.0 ? 0.01 * ar : 0.0);
        }
      }
      std::vector<PointSummary> points;
      for (std::size_t a = 0; a < k_x.size(); ++a) {
        std::vector<double> v;
        for (int s = 0; s < runs[a]; ++s) v.push_back(1.0 + effect[s][a] + 0.005 * normal(rng));
        points.push_back(point(v, 1));
      }
      std::vector<Measurement> y;
      for (const auto& p : points) y.push_back(p.A);
      const double slope = fit_line(k_x, y).slope;
      sum += slope;
      sum2 += slope * slope;
      jackknife2 += std::pow(*slope_error_over_shared_seeds(k_x, pointers(points)), 2);
      independent2 += std::pow(independent_slope_error(points), 2);
    }
    const double sd = std::sqrt(sum2 / ensembles - std::pow(sum / ensembles, 2));
    const double jackknife = std::sqrt(jackknife2 / ensembles);
    const double independent = std::sqrt(independent2 / ensembles);
    BOOST_TEST_MESSAGE(c.name << ": slope sd " << sd << ", jackknife " << jackknife
                              << ", fit's own " << independent);
    // The sd of 4000 slopes is known to about 1.1 %. The jackknife keeps the weights of the
    // ensemble at hand, the slopes' scatter includes that of the weights: it ends 1-4 % low.
    BOOST_TEST(std::abs(jackknife / sd - 1.0) < 0.08,
               c.name << ": jackknife/sd = " << jackknife / sd);
    if (c.rho > 0.0)  // nearby points move together: the fit's own error is far too small
      BOOST_TEST(independent / sd < 0.8, c.name << ": own/sd = " << independent / sd);
  }
}
