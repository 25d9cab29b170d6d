// Invariants of the engine: energy and momentum conservation in elastic runs, the energy lost per
// inelastic collision, no overlaps (full checks every few thousand events), bit-for-bit
// reproducibility, the TC model, and the collapse stop.
#define BOOST_TEST_MODULE sim_invariants
#include <boost/test/unit_test.hpp>
#include <chrono>
#include <cmath>
#include <sstream>

#include "molchaos/sim/csv.hpp"
#include "molchaos/sim/engine.hpp"
#include "molchaos/sim/run.hpp"

using namespace molchaos::sim;

namespace {

constexpr std::uint64_t k_check_every = 3000;  // full overlap check (throws on overlap)

template <int D>
void elastic_conservation(Parameters p, std::uint64_t collisions) {
  p.dimension = D;
  p.restitution = 1.0;
  Engine<D> engine(p);
  engine.relax(p.relax_collisions_per_particle);
  engine.set_debug_overlap_check(k_check_every);
  const double energy0 = engine.kinetic_energy();
  const auto momentum0 = engine.momentum();
  engine.set_collision_limit(collisions);
  BOOST_TEST((engine.advance_to(1e12) == Engine<D>::Status::stopped));
  BOOST_TEST((engine.stop_reason() == StopReason::max_collisions));
  BOOST_TEST(engine.collisions() == collisions);
  const double drift = std::fabs(engine.kinetic_energy() / energy0 - 1);
  BOOST_TEST_MESSAGE("d = " << D << ", " << collisions << " collisions: relative energy drift "
                            << drift << ", min distance " << engine.min_pair_distance());
  BOOST_TEST(drift < 1e-12);
  // Momentum: zero to rounding (each collision conserves it to ~1e-16 of the pair's momentum).
  const auto momentum = engine.momentum();
  for (int a = 0; a < D; ++a) BOOST_TEST(std::fabs(momentum[a] - momentum0[a]) < 1e-10);
  BOOST_TEST(engine.min_pair_distance() >= 1 - 1e-10);
}

// Every collision removes exactly (1 - eps^2)/4 (g.e)^2 from the total kinetic energy; shuffles
// conserve it.
template <int D>
void energy_loss_per_collision(Randomization mode, double density) {
  Parameters p;
  p.dimension = D;
  p.particles = 400;
  p.density = density;
  p.restitution = 0.8;
  p.randomize = mode;
  p.relax_collisions_per_particle = 2;
  Engine<D, LastCollision> engine(p);
  engine.relax(p.relax_collisions_per_particle);
  engine.set_debug_overlap_check(k_check_every);
  std::uint64_t checked = 0;
  double worst = 0;
  while (checked < 5000) {
    const double before = engine.kinetic_energy();
    const std::uint64_t collisions = engine.collisions();
    engine.step();
    if (engine.collisions() == collisions) continue;
    const CollisionRecord& c = engine.observer().record;
    const double eps = c.made_elastic ? 1.0 : p.restitution;
    const double expected = (1 - eps * eps) / 4 * c.normal_velocity * c.normal_velocity;
    // The loss the rule reports is its formula (exact but for the product's rounding).
    BOOST_TEST(c.energy_lost == expected, boost::test_tools::tolerance(1e-14));
    const double lost = before - engine.kinetic_energy();
    // Rounding of the sums of N terms: a few ulps of the total energy.
    worst = std::max(worst, std::fabs(lost - expected) / before);
    // The pair alone, before any shuffle: exact up to the rounding of the pair's energy (a few
    // ulps of energy_before; a grazing collision loses far less than that scale).
    const double pair_lost = c.energy_before - c.energy_after;
    BOOST_TEST(std::fabs(pair_lost - expected) <= 1e-14 * c.energy_before);
    ++checked;
  }
  BOOST_TEST_MESSAGE("d = " << D << " n = " << p.density << " mode " << to_string(mode)
                            << ": worst |lost - rule| / E = " << worst);
  BOOST_TEST(worst < 1e-13);
}

std::string csv_of(const Parameters& p) {
  std::ostringstream out;
  write_csv(run(p), out);
  return out.str();
}

}  // namespace

BOOST_AUTO_TEST_CASE(elastic_2d_conserves_energy_and_momentum) {
  Parameters p;
  p.particles = 2000;
  p.density = 0.1;
  elastic_conservation<2>(p, 100000);
}

BOOST_AUTO_TEST_CASE(elastic_3d_conserves_energy_and_momentum) {
  Parameters p;
  p.particles = 2000;
  p.density = 0.5;
  elastic_conservation<3>(p, 100000);
}

BOOST_AUTO_TEST_CASE(elastic_dense_3d_no_overlaps) {
  Parameters p;
  p.dimension = 3;
  p.particles = 1000;
  p.density = 0.4 * 6 / 3.141592653589793;  // packing fraction 0.4, lattice start
  p.relax_collisions_per_particle = 5;
  elastic_conservation<3>(p, 50000);
}

BOOST_AUTO_TEST_CASE(energy_lost_per_collision_is_the_rules) {
  for (auto mode : {Randomization::none, Randomization::paper, Randomization::flux}) {
    energy_loss_per_collision<2>(mode, 0.1);
    energy_loss_per_collision<3>(mode, 0.2);
    energy_loss_per_collision<3>(mode, 0.7);  // packing 0.37: neighbour lists
  }
}

BOOST_AUTO_TEST_CASE(same_seed_gives_byte_identical_csv) {
  Parameters p;
  p.particles = 1000;
  p.density = 0.1;
  p.restitution = 0.9;
  p.t_end = 50;
  p.contact_statistics = true;
  for (auto mode : {Randomization::none, Randomization::paper, Randomization::flux}) {
    p.randomize = mode;
    const std::string a = csv_of(p), b = csv_of(p);
    BOOST_TEST(a == b);
    Parameters other = p;
    other.seed = 2;
    BOOST_TEST(csv_of(other) != a);
  }
  p.dimension = 3;
  p.density = 0.3;
  p.t_end = 10;
  BOOST_TEST(csv_of(p) == csv_of(p));
}

BOOST_AUTO_TEST_CASE(cooling_run_keeps_time_exact_through_rescaling) {
  // Strong cooling: T falls by orders of magnitude, velocities are rescaled many times; the
  // samples land exactly on the grid and T decreases monotonically.
  Parameters p;
  p.particles = 1000;
  p.density = 0.05;
  p.restitution = 0.5;
  p.randomize = Randomization::flux;
  p.t_end = 1000;
  const RunResult r = run(p);
  BOOST_TEST((r.stop_reason == StopReason::t_end));
  const auto grid = sample_times(p);
  BOOST_REQUIRE(r.samples.size() == grid.size());
  for (std::size_t k = 0; k < grid.size(); ++k) BOOST_TEST(r.samples[k].t == grid[k]);
  for (std::size_t k = 1; k < grid.size(); ++k)
    BOOST_TEST(r.samples[k].temperature <= r.samples[k - 1].temperature);
  BOOST_TEST_MESSAGE("T(t_end) = " << r.samples.back().temperature);
  BOOST_TEST(r.samples.back().temperature < 1e-3);
}

BOOST_AUTO_TEST_CASE(tc_model_makes_recent_colliders_elastic) {
  // With tc far longer than the run every collision after a particle's first is elastic.
  Parameters p;
  p.particles = 500;
  p.density = 0.1;
  p.restitution = 0.5;
  p.tc = 1e9;
  Engine<2, LastCollision> engine(p);
  engine.relax(2);
  std::uint64_t elastic = 0, total = 0;
  while (total < 3000) {
    const std::uint64_t collisions = engine.collisions();
    engine.step();
    if (engine.collisions() == collisions) continue;
    ++total;
    if (engine.observer().record.made_elastic) ++elastic;
  }
  // At most N/2 collisions can be a pair's first collision... each particle is first once.
  BOOST_TEST(total - elastic <= 500u);
  BOOST_TEST(elastic > 2000u);
}

BOOST_AUTO_TEST_CASE(collapse_stops_the_run_with_a_reason) {
  Parameters p;
  p.particles = 1000;
  p.density = 0.3;
  p.restitution = 0.2;
  p.t_end = 1e6;
  p.max_collisions = 200'000'000;  // a bound, not expected to be reached
  const auto start = std::chrono::steady_clock::now();
  const RunResult r = run(p);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  BOOST_TEST_MESSAGE("stop: " << stop_message(r) << " after " << r.collisions << " collisions, "
                              << seconds << " s");
  BOOST_TEST((r.stop_reason == StopReason::collapse));
  BOOST_TEST(stop_message(r).rfind("collapse: ", 0) == 0);
  BOOST_TEST(seconds < 60);
  // With the TC model the same run goes on to t_end.
  p.tc = 1e-4;
  p.t_end = 100;
  const RunResult with_tc = run(p);
  BOOST_TEST((with_tc.stop_reason == StopReason::t_end));
}

BOOST_AUTO_TEST_CASE(simultaneous_and_grazing_collisions) {
  // Four disks in a box of side 10. Disks 1 and 2 hit disk 0 (at rest) from both sides at the
  // same instant t = 1; elastic hard disks in a row end with the outer ones flying apart and the
  // middle one at rest. Disk 3 grazes disk 0's final position region with impact parameter
  // exactly sigma, far later, and must pass undeflected.
  Parameters p;
  p.particles = 4;
  p.density = 0.04;  // box side 10
  p.relax_collisions_per_particle = 0;
  Engine<2> engine(p);
  BOOST_REQUIRE(engine.box() == 10.0);
  const std::vector<double> r = {5, 5, 3, 5, 7, 5, 1, 2};
  const std::vector<double> v = {0, 0, 1, 0, -1, 0, 0.5, 0};
  engine.set_state(r, v);
  engine.set_debug_overlap_check(1);
  const double energy = engine.kinetic_energy();
  BOOST_TEST((engine.advance_to(1.5) == Engine<2>::Status::reached));
  BOOST_TEST(engine.collisions() == 3u);  // 1-0, 0-2, 0-1 at t = 1 (zero time apart)
  const Snapshot s = engine.snapshot();
  BOOST_TEST(s.velocities[0] == 0.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s.velocities[2] == -1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s.velocities[4] == 1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(engine.kinetic_energy() == energy, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(engine.min_pair_distance() >= 1 - 1e-10);

  // Grazing: disk 1 moves along y = 6 past disk 0 at (5, 5): contact at zero normal speed.
  const std::vector<double> r2 = {5, 5, 2, 6, 8, 1, 1, 9};
  const std::vector<double> v2 = {0, 0, 1, 0, 0, 0, 0, 0};
  engine.set_state(r2, v2);
  BOOST_TEST((engine.advance_to(5.0) == Engine<2>::Status::reached));
  const Snapshot g = engine.snapshot();
  BOOST_TEST(g.velocities[2] == 1.0);
  BOOST_TEST(g.velocities[3] == 0.0);
  BOOST_TEST(g.velocities[0] == 0.0);
  BOOST_TEST(engine.min_pair_distance() >= 1 - 1e-10);
}
