// Unit tests of the internal clock: restarts with velocity rescaling keep physical times and
// velocities (exactly when the factors are powers of two, to rounding otherwise).
#define BOOST_TEST_MODULE sim_internal_clock
#include <boost/test/unit_test.hpp>

#include "molchaos/sim/internal_clock.hpp"

using namespace molchaos::sim;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_CASE(fresh_clock_is_physical) {
  const InternalClock clock;
  BOOST_TEST(clock.time() == 0.0);
  BOOST_TEST(clock.internal_time(3.5) == 3.5);
  BOOST_TEST(clock.physical_velocity(2.0) == 2.0);
}

BOOST_AUTO_TEST_CASE(restart_keeps_physical_time_and_velocity) {
  // A gas whose speed halves: u -> 2 u keeps internal speeds of order 1; theta doubles.
  InternalClock clock;
  clock.now = 10.0;  // 10 physical time units passed at u = v
  const double u = 0.25, last_collision = 7.0;
  const double v = clock.physical_velocity(u);
  const double t_last = clock.t_offset + clock.theta * last_collision;
  const double rebased = clock.restarted(last_collision, 2.0);
  clock.restart(2.0);
  BOOST_TEST(clock.now == 0.0);
  BOOST_TEST(clock.time() == 10.0);  // exact: powers of two
  BOOST_TEST(clock.physical_velocity(2.0 * u) == v);
  BOOST_TEST(clock.t_offset + clock.theta * rebased == t_last);  // the past keeps its time
  // tau advances in larger physical steps now: 1 internal unit = 2 physical ones.
  clock.now = 1.5;
  BOOST_TEST(clock.time() == 13.0);
  BOOST_TEST(clock.internal_time(13.0) == 1.5);
  BOOST_TEST(clock.physical_interval(0.5) == 1.0);
}

BOOST_AUTO_TEST_CASE(many_restarts_keep_relative_precision) {
  // 200 restarts by factor 1.3 (theta grows by 23 decades) with one internal unit of time each:
  // the physical time is sum theta_k, compared with the geometric series.
  InternalClock clock;
  double expected = 0, theta = 1;
  for (int k = 0; k < 200; ++k) {
    clock.now = 1.0;
    expected += theta;
    clock.restart(1.3);
    theta *= 1.3;
  }
  BOOST_TEST(clock.theta == theta, tt::tolerance(1e-13));
  // Rounding: about one ulp per step for 200 steps.
  BOOST_TEST(clock.time() == expected, tt::tolerance(1e-13));
  BOOST_TEST(clock.internal_time(clock.time()) == 0.0);
}
