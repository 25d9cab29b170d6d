// The break-down detector of the fit-window rule: its thresholds against the exponential law of
// |mode|² in a homogeneous gas, and the relaxed initial state that fired the former hand-set
// threshold (5) in every mode and restitution of a sweep at n = 0.05.
#define BOOST_TEST_MODULE validation_breakdown_detector
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "molchaos/sim/run.hpp"
#include "molchaos/validation/hcs_window.hpp"
#include "molchaos/validation/sweep.hpp"

using namespace molchaos;
using namespace molchaos::validation;

BOOST_AUTO_TEST_CASE(gamma_tail_closed_forms) {
  // Gamma(1): e^{-y}; Gamma(2): (1 + y) e^{-y}; Gamma(4): (1 + y + y²/2 + y³/6) e^{-y}.
  for (double y : {0.5, 3.0, 17.0}) {
    BOOST_TEST(std::abs(gamma_upper_tail(1, y) - std::exp(-y)) <= 1e-15);
    BOOST_TEST(std::abs(gamma_upper_tail(2, y) / ((1 + y) * std::exp(-y)) - 1) <= 1e-14);
    const double q4 = (1 + y + y * y / 2 + y * y * y / 6) * std::exp(-y);
    BOOST_TEST(std::abs(gamma_upper_tail(4, y) / q4 - 1) <= 1e-14);
  }
  for (int terms : {1, 2, 4, 9})
    for (double p : {0.5, 1e-3, 1.25e-6}) {
      const double y = gamma_upper_quantile(terms, p);
      BOOST_TEST(std::abs(gamma_upper_tail(terms, y) / p - 1) <= 1e-9);
    }
}

BOOST_AUTO_TEST_CASE(default_thresholds_follow_the_false_alarm_budget) {
  const WindowRule rule;
  const double per_sample = k_false_alarm_per_run / (2.0 * k_watched_samples);
  // d = 2: density_mode·2 ~ Gamma(2), velocity_mode·4 ~ Gamma(4) at equilibrium (S ≤ 1).
  BOOST_TEST(std::abs(gamma_upper_tail(2, 2 * rule.density_mode_threshold) / per_sample - 1) <=
             1e-9);
  BOOST_TEST(std::abs(gamma_upper_tail(4, 4 * rule.velocity_mode_threshold) / per_sample - 1) <=
             1e-9);
  // d = 3 has lighter tails, so its own thresholds are lower: the d = 2 defaults are safe there.
  const ModeThresholds t3 = equilibrium_mode_thresholds(3, per_sample);
  BOOST_TEST(t3.density_mode < rule.density_mode_threshold);
  BOOST_TEST(t3.velocity_mode < rule.velocity_mode_threshold);
}

// `molchaos sweep --particles 5000 --density 0.05,0.1 --restitution 0.8,...,0.98 --randomize
// none,paper,flux --seeds 256 --base-seed 7771`: seed index 136 starts (after the elastic
// relaxation, the same at every ε and mode) with a largest-scale density fluctuation
// density_mode = 5.48 that persists through the transient (it relaxes on the sound and heat
// times of the box, hundreds of time units). Under the equilibrium law that is a 1-in-3·10⁴
// sample; the former threshold 5 declared the state broken down before the fit could start.
BOOST_AUTO_TEST_CASE(relaxed_equilibrium_fluctuation_is_not_a_breakdown) {
  sim::Parameters p;
  p.dimension = 2;
  p.particles = 5000;
  p.density = 0.05;
  p.restitution = 0.93;
  p.seed = derive_seed(7771, 136);
  p.t_end = 40.0;  // past the transient (3 collisions per particle at t ≈ 17)
  p.samples_per_decade = 40;
  const sim::RunResult r = sim::run(p);
  double largest = 0;
  for (const auto& s : r.samples)
    if (s.t > 0 && s.t < 20) largest = std::max(largest, s.density_mode);
  BOOST_TEST_REQUIRE(largest > 5.0);  // the fluctuation the former rule fired on
  const FitWindow w = choose_window(r.samples, p.particles, WindowRule{});
  BOOST_TEST(w.valid, w.message);
  BOOST_TEST(!w.breakdown.detected);
}
