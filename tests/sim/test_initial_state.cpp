// Unit tests of the initial state: positions in the box without overlap (random insertion and the
// lattices), Maxwell velocities with zero momentum and T = 1, the same seed giving the same state,
// the error for a density no lattice reaches, and an interrupt of the build.
#define BOOST_TEST_MODULE sim_initial_state
#include <atomic>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

#include "molchaos/sim/engine.hpp"
#include "molchaos/sim/initial_state.hpp"

using namespace molchaos::sim;

namespace {

template <int D>
double side(std::int32_t n, double density) {
  return std::pow(n / density, 1.0 / D);
}

// Smallest periodic pair distance, by all pairs.
template <int D>
double min_distance(const std::vector<double>& r, std::int32_t n, double box) {
  double best = 1e300;
  for (std::int32_t i = 0; i < n; ++i)
    for (std::int32_t j = i + 1; j < n; ++j) {
      double d2 = 0;
      for (int a = 0; a < D; ++a) {
        double d = std::fabs(r[D * i + a] - r[D * j + a]);
        d = std::min(d, box - d);
        d2 += d * d;
      }
      best = std::min(best, d2);
    }
  return std::sqrt(best);
}

template <int D>
void check_positions(std::int32_t n, double density) {
  const double box = side<D>(n, density);
  Rng rng(5);
  const std::vector<double> r = place_particles<D>(n, box, rng);
  BOOST_REQUIRE(r.size() == static_cast<std::size_t>(D * n));
  for (double x : r) BOOST_TEST((x >= 0 && x < box));
  const double closest = min_distance<D>(r, n, box);
  BOOST_TEST_MESSAGE("d = " << D << " n = " << density << ": closest pair " << closest);
  BOOST_TEST(closest > 1.0);
  Rng again(5);
  BOOST_TEST((place_particles<D>(n, box, again) == r));  // same seed, same bytes
}

template <int D>
void check_velocities(std::int32_t n) {
  Rng rng(9);
  const std::vector<double> v = maxwell_velocities<D>(n, rng);
  double sum2 = 0, momentum[D] = {};
  for (std::int32_t i = 0; i < n; ++i)
    for (int a = 0; a < D; ++a) {
      sum2 += v[D * i + a] * v[D * i + a];
      momentum[a] += v[D * i + a];
    }
  // Rounding: a few ulps per term of sums of n terms of order 1.
  BOOST_TEST(sum2 / (n * D) == 1.0, boost::test_tools::tolerance(1e-13));
  for (int a = 0; a < D; ++a) BOOST_TEST(std::fabs(momentum[a]) < 1e-12 * n);
}

}  // namespace

BOOST_AUTO_TEST_CASE(disks_without_overlap_by_insertion_and_lattice) {
  check_positions<2>(400, 0.05);  // insertion
  check_positions<2>(400, 0.5);   // packing 0.39: staggered lattice
  check_positions<2>(400, 1.05);  // beyond random close packing
}

BOOST_AUTO_TEST_CASE(spheres_without_overlap_by_insertion_and_lattice) {
  check_positions<3>(400, 0.1);  // insertion
  check_positions<3>(400, 0.7);  // packing 0.37: simple cubic lattice (reaches n < 0.78)
}

BOOST_AUTO_TEST_CASE(velocities_have_zero_momentum_and_unit_temperature) {
  check_velocities<2>(1000);
  check_velocities<3>(1000);
}

BOOST_AUTO_TEST_CASE(unreachable_density_names_the_reachable_one) {
  Rng rng(1);
  try {
    place_particles<3>(1000, side<3>(1000, 1.3), rng);
    BOOST_ERROR("no error for spheres at n = 1.3");
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    BOOST_TEST(message.find("too high") != std::string::npos);
    BOOST_TEST(message.find("reaches n <") != std::string::npos);
  }
}

BOOST_AUTO_TEST_CASE(a_set_interrupt_stops_the_build_and_an_unset_one_changes_nothing) {
  const std::atomic<bool> set{true}, unset{false};
  for (const double density : {0.05, 1.05}) {  // insertion, lattice
    const double box = side<2>(1000, density);
    Rng rng(3), again(3), stopped(3);
    BOOST_TEST(
        (place_particles<2>(1000, box, rng, &unset) == place_particles<2>(1000, box, again)));
    BOOST_CHECK_THROW(place_particles<2>(1000, box, stopped, &set), InitialStateInterrupted);
  }
  Parameters p;
  p.particles = 1000;
  p.density = 0.05;
  BOOST_CHECK_THROW(Engine<2>(p, &set), InitialStateInterrupted);
  p.dimension = 3;
  p.density = 0.6;  // neighbour lists
  BOOST_CHECK_THROW(Engine<3>(p, &set), InitialStateInterrupted);
  const Engine<3> built(p, &unset), plain(p);
  BOOST_TEST((built.snapshot().positions == plain.snapshot().positions));
  BOOST_TEST((built.snapshot().velocities == plain.snapshot().velocities));
}
