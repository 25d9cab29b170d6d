// The run-length estimate behind the refusal of endless runs: Haff's law in closed form, the TC
// model's integration against its two limits (no effect, and no cooling), the stop temperature,
// and the longest allowed time, shown to three digits and itself allowed.
#define BOOST_TEST_MODULE run_length
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "molchaos/sim/run_length.hpp"

using namespace molchaos::sim;

namespace {
RunLengthGas gas(double restitution, double tc, double stop_temperature = 1e-300) {
  return {2, 0.1887, restitution, tc, stop_temperature};
}
double haff(const RunLengthGas& g, double t) {  // ω_E τ0 ln(1 + t/τ0)
  const double tau0 =
      2.0 * g.dimension / ((1 - g.restitution * g.restitution) * g.collision_frequency);
  return g.collision_frequency * tau0 * std::log1p(t / tau0);
}
}  // namespace

BOOST_AUTO_TEST_CASE(elastic_gas_collides_at_its_initial_rate) {
  BOOST_TEST(estimated_collisions_per_particle(gas(1.0, 0.0), 1e4) == 0.1887 * 1e4,
             boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(cooling_gas_follows_haffs_law_to_its_stop_temperature) {
  for (double eps : {0.5, 0.9, 0.99})
    for (double t : {1e-3, 1.0, 1e3, 1e9}) {
      BOOST_TEST_INFO("eps = " << eps << ", t = " << t);
      BOOST_TEST(estimated_collisions_per_particle(gas(eps, 0.0), t) == haff(gas(eps, 0.0), t),
                 boost::test_tools::tolerance(1e-14));
    }
  // T = (1 + t/τ0)^−2 reaches 1e-4 at t = 99 τ0: no collisions after it.
  const RunLengthGas g = gas(0.9, 0.0, 1e-4);
  const double tau0 = 4.0 / (0.19 * 0.1887);
  BOOST_TEST(estimated_collisions_per_particle(g, 1e9) == haff(g, 99 * tau0),
             boost::test_tools::tolerance(1e-12));
}

// The TC integration (RK4 in ln t) against its limits: a tc far below the time between
// collisions leaves Haff's law (to the integration's accuracy), a tc far above it leaves every
// collision elastic (ω_E t), and a longer tc never gives fewer collisions.
BOOST_AUTO_TEST_CASE(tc_model_lies_between_haffs_law_and_no_cooling) {
  for (double eps : {0.5, 0.9})
    for (double t : {10.0, 1e4, 1e8}) {
      BOOST_TEST_INFO("eps = " << eps << ", t = " << t);
      BOOST_TEST(estimated_collisions_per_particle(gas(eps, 1e-12), t) == haff(gas(eps, 0.0), t),
                 boost::test_tools::tolerance(1e-6));
      BOOST_TEST(estimated_collisions_per_particle(gas(eps, 1e10), t) == 0.1887 * t,
                 boost::test_tools::tolerance(1e-6));
      double previous = 0;
      for (double tc : {0.1, 1.0, 10.0, 100.0}) {
        const double c = estimated_collisions_per_particle(gas(eps, tc), t);
        BOOST_TEST(c >= previous);
        BOOST_TEST(c <= 0.1887 * t * (1 + 1e-9));
        previous = c;
      }
    }
  // The stop temperature ends the TC run's collisions too.
  const double stopped = estimated_collisions_per_particle(gas(0.5, 1.0, 1e-2), 1e12);
  BOOST_TEST(stopped == estimated_collisions_per_particle(gas(0.5, 1.0, 1e-2), 1e14),
             boost::test_tools::tolerance(1e-12));
}

// Was: the bisection took √(lo·hi), which overflowed for t_end near the largest double and
// named 1e8 where 1.62e9 was allowed; and it printed 17 digits of an estimate.
BOOST_AUTO_TEST_CASE(longest_time_is_three_digits_rounded_down_and_allowed) {
  const auto cost = [](double t) { return 2.0 * t; };
  for (double t_end : {1e5, 1e100, 1e308}) {
    const double longest = longest_time_within(cost, t_end, 2468.2468);
    BOOST_TEST_INFO("t_end = " << t_end);
    BOOST_TEST(longest == 1230.0);
    BOOST_TEST(cost(longest) <= 2468.2468);
  }
  BOOST_TEST(longest_time_within(cost, 1000.0, 2468.2468) == 1000.0);
}
