// validation/verdict.hpp: the one agreement rule at its edges (exactly 3 combined standard
// errors, zero errors, exact closed forms) and the bound rule.
#define BOOST_TEST_MODULE validation_verdict
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "molchaos/validation/proportional_fit.hpp"
#include "molchaos/validation/verdict.hpp"

using namespace molchaos::validation;

BOOST_AUTO_TEST_CASE(agreement_uses_the_combined_standard_error) {
  // σ = √(0.3² + 0.4²) = 0.5, so the limit is 1.5.
  const Agreement inside = agreement({11.49, 0.3}, {10.0, 0.4});
  BOOST_TEST(inside.agrees);
  BOOST_TEST(*inside.difference_in_se == 2.98, boost::test_tools::tolerance(1e-12));
  const Agreement outside = agreement({11.51, 0.3}, {10.0, 0.4});
  BOOST_TEST(!outside.agrees);
  BOOST_TEST(*outside.difference_in_se == 3.02, boost::test_tools::tolerance(1e-12));
  // Symmetric in sign.
  BOOST_TEST(!agreement({8.49, 0.3}, {10.0, 0.4}).agrees);
}

BOOST_AUTO_TEST_CASE(exact_values_agree_only_to_rounding) {
  // Closed forms without error: 3/16 computed as 0.1875 agrees, -1.5 against -63/40 does not.
  const Agreement same = agreement({3.0 / 16.0 * (1.0 + 1e-15), 0.0}, {0.1875, 0.0});
  BOOST_TEST(same.agrees);
  BOOST_TEST(!same.difference_in_se.has_value());
  BOOST_TEST(!agreement({-1.5, 0.0}, {-63.0 / 40.0, 0.0}).agrees);
}

BOOST_AUTO_TEST_CASE(bound_rule_needs_three_standard_errors_of_room) {
  BOOST_TEST(significantly_below({0.5, 0.03}, 0.6));   // 0.59 < 0.6
  BOOST_TEST(!significantly_below({0.5, 0.04}, 0.6));  // 0.62 > 0.6
  BOOST_TEST(!significantly_below({0.7, 0.0}, 0.6));
}

BOOST_AUTO_TEST_CASE(proportional_fit_exact_and_noisy) {
  // Exact data y = 1.7 x: the ratio to round-off, χ² of the fit zero, "equal" rejected.
  std::vector<Measurement> x, y;
  for (int i = 1; i <= 10; ++i) {
    x.push_back({0.01 * i, 0.002});
    y.push_back({0.017 * i, 0.003});
  }
  const ProportionalFit exact = fit_proportional(y, x);
  BOOST_TEST(exact.ratio.value == 1.7, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(exact.chi2_of_fit < 1e-20);
  BOOST_TEST(exact.points == 10);
  BOOST_TEST(exact.p_equal < k_global_p_threshold);
  // Noisy data drawn with y = x: over 400 repetitions the fitted ratio scatters by its reported
  // error (pulls of unit variance within 3 SE of the variance's sampling error) and "equal"
  // is rejected about as often as its threshold says (at most a handful of times).
  std::mt19937_64 rng(11);
  std::normal_distribution<double> unit;
  double sum_pull2 = 0.0;
  int rejected = 0;
  const int reps = 400;
  for (int r = 0; r < reps; ++r) {
    std::vector<Measurement> xs, ys;
    for (int i = 1; i <= 20; ++i) {
      const double truth = 0.005 * i, sx = 0.004, sy = 0.006;
      xs.push_back({truth + sx * unit(rng), sx});
      ys.push_back({truth + sy * unit(rng), sy});
    }
    const ProportionalFit f = fit_proportional(ys, xs);
    sum_pull2 += std::pow((f.ratio.value - 1.0) / f.ratio.error, 2);
    if (f.p_equal < k_global_p_threshold) ++rejected;
  }
  const double pull_variance = sum_pull2 / reps;
  BOOST_TEST(std::abs(pull_variance - 1.0) < 3.0 * std::sqrt(2.0 / reps));
  BOOST_TEST(rejected <= 5);  // expected 400 × 0.0027 ≈ 1.1; P(> 5) ≈ 1e-3
}
