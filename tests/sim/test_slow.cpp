// Slow tests (label slow, run by `make test-all`): 10^6-collision conservation in d = 2 and 3,
// N = 10^6 disks, a run of 10^8 events.
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

// Extremes. N = 10^6 disks: the engine builds, relaxes and runs 10^6 elastic collisions
// with every invariant, in under 300 bytes per particle.
BOOST_AUTO_TEST_CASE(one_million_disks) {
  Parameters p;
  p.particles = 1'000'000;
  p.density = 0.05;
  Engine<2> engine(p);
  engine.relax(1);
  const double bytes = static_cast<double>(engine.memory_bytes()) / 1e6;
  const double energy0 = engine.kinetic_energy();
  engine.set_collision_limit(engine.collisions() + 1'000'000);
  engine.advance_to(1e12);
  const double drift = std::fabs(engine.kinetic_energy() / energy0 - 1);
  BOOST_TEST_MESSAGE("N = 1e6: " << bytes << " engine bytes per particle, energy drift " << drift
                                 << " over 1e6 collisions");
  BOOST_TEST(bytes < 300);
  BOOST_TEST(drift < 1e-12);
  for (double m : engine.momentum()) BOOST_TEST(std::fabs(m) < 1e-8);
  BOOST_TEST(engine.min_pair_distance() >= 1 - 1e-10);
}

// A long run: 10^8 events (about 1.5e7 collisions) of the paper's system, elastic, with a full
// overlap check every 10^6 events; energy, momentum and Enskog's collision frequency hold.
BOOST_AUTO_TEST_CASE(hundred_million_events) {
  Parameters p;
  p.particles = 5000;
  p.density = 0.05;
  Engine<2> engine(p);
  engine.relax(20);
  engine.set_debug_overlap_check(1'000'000);
  const double energy0 = engine.kinetic_energy();
  const auto status = engine.advance_to(1e15, 100'000'000);
  BOOST_TEST((status == Engine<2>::Status::paused));
  BOOST_TEST(engine.events() == 100'000'000u);
  const double drift = std::fabs(engine.kinetic_energy() / energy0 - 1);
  const double omega = 2.0 * static_cast<double>(engine.collisions()) / (5000.0 * engine.time());
  const double omega_enskog = 2.0 * p.density *
                              (1 - 7.0 / 16 * 3.141592653589793 / 4 * p.density) /
                              std::pow(1 - 3.141592653589793 / 4 * p.density, 2) *
                              std::sqrt(3.141592653589793 * engine.temperature());
  BOOST_TEST_MESSAGE("1e8 events: " << engine.collisions() << " collisions, t = " << engine.time()
                                    << ", energy drift " << drift << ", omega/omega_E "
                                    << omega / omega_enskog);
  BOOST_TEST(drift < 1e-12);
  for (double m : engine.momentum()) BOOST_TEST(std::fabs(m) < 1e-10);
  BOOST_TEST(engine.min_pair_distance() >= 1 - 1e-10);
  // ~1.5e7 collisions: statistical error of omega ~0.03 %; finite N ~0.1 % (README table).
  BOOST_TEST(omega / omega_enskog == 1.0, boost::test_tools::tolerance(0.005));
}
