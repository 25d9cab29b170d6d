// Slow tests (label slow, run by `make test-all`): 10^6-collision conservation in d = 2 and 3.
#define BOOST_TEST_MODULE sim_slow
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "molchaos/sim/engine.hpp"

using namespace molchaos::sim;

namespace {
template <int D>
void conserve(double density) {
  Parameters p;
  p.dimension = D;
  p.particles = 5000;
  p.density = density;
  Engine<D> engine(p);
  engine.relax(20);
  engine.set_debug_overlap_check(5000);
  const double energy0 = engine.kinetic_energy();
  engine.set_collision_limit(1'000'000);
  engine.advance_to(1e12);
  BOOST_TEST(engine.collisions() == 1'000'000u);
  const double drift = std::fabs(engine.kinetic_energy() / energy0 - 1);
  BOOST_TEST_MESSAGE("d = " << D << ": energy drift over 1e6 collisions " << drift);
  BOOST_TEST(drift < 1e-12);
  for (double m : engine.momentum()) BOOST_TEST(std::fabs(m) < 1e-10);
  BOOST_TEST(engine.min_pair_distance() >= 1 - 1e-10);
}
}  // namespace

BOOST_AUTO_TEST_CASE(elastic_2d_1e6_collisions) { conserve<2>(0.05); }
BOOST_AUTO_TEST_CASE(elastic_3d_1e6_collisions) { conserve<3>(0.4 * 6 / 3.141592653589793); }
