// Numerical stress, fast cases (label invariant; the long ones are in test_slow.cpp).
// Each case prints what it found (run with --log_level=message to see it):
//  - inelastic collapse, eps = 0.1, 0.3, 0.5 at n = 0.1, 0.3, 0.5 in 2D: without the TC model the
//    run ends in bounded time with a stated reason and never overlaps; with it, it reaches t_end
//    with no pair closer than sigma (1 - 1e-10);
//  - dense initial states up to and beyond random close packing either generate (no overlap,
//    relaxation conserves energy) or fail with a message that names the density and the limit;
//  - N = 2: two disks cooling over 24 decades of temperature, collision times and temperatures
//    against their closed forms;
//  - a gas of 1000 disks cooled to T/T0 < 1e-12 keeps energy conservation and Enskog's
//    collision frequency at that temperature.
#define BOOST_TEST_MODULE test_sim_stress
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "molchaos/sim/engine.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/theory/contact_value.hpp"

using namespace molchaos::sim;
namespace data = boost::unit_test::data;
namespace tt = boost::test_tools;

namespace {
constexpr double k_min_distance = 1.0 - 1e-10;

Parameters stress_case(double restitution, double density) {
  Parameters p;
  p.particles = 1000;
  p.density = density;
  p.restitution = restitution;
  p.relax_collisions_per_particle = 5;
  p.t_end = 1e4;
  return p;
}
double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

// The case eps = 0.3, n = 0.1 (seed 1) once looped for ever at a frozen time (a contact with
// vanishing normal velocity judged "approaching" by the prediction and "separating" by the
// collision); it must now end with the collapse message like the others.
BOOST_DATA_TEST_CASE(collapse_without_tc_ends_in_bounded_time_without_overlap,
                     data::make({0.1, 0.3, 0.5}) * data::make({0.1, 0.3, 0.5}), restitution,
                     density) {
  const Parameters p = stress_case(restitution, density);
  Engine<2> engine(p);
  engine.relax(p.relax_collisions_per_particle);
  engine.set_collision_limit(5'000'000);  // the work bound for a run that neither collapses nor ends
  engine.set_debug_overlap_check(5000);   // full overlap check every 5000 events (throws)
  const auto start = std::chrono::steady_clock::now();
  const auto status = engine.advance_to(p.t_end);
  const double seconds = seconds_since(start);
  const StopReason reason =
      status == Engine<2>::Status::reached ? StopReason::t_end : engine.stop_reason();
  BOOST_TEST_MESSAGE("eps = " << restitution << ", n = " << density << ", no TC: '"
                              << describe(reason, engine.time())
                              << "' after " << engine.collisions() << " collisions, t = "
                              << engine.time() << ", T = " << engine.temperature() << ", "
                              << seconds << " s");
  BOOST_TEST((reason == StopReason::t_end || reason == StopReason::max_collisions ||
              reason == StopReason::collapse),
             "stop reason '" << to_string(reason) << "'");
  BOOST_TEST(seconds < 60.0);
  BOOST_TEST(engine.min_pair_distance() >= k_min_distance);
  if (restitution == 0.3 && density == 0.1) BOOST_TEST((reason == StopReason::collapse));
}

BOOST_DATA_TEST_CASE(tc_model_survives_collapse_without_overlap,
                     data::make({0.1, 0.3, 0.5}) * data::make({0.1, 0.3, 0.5}), restitution,
                     density) {
  Parameters p = stress_case(restitution, density);
  p.tc = 1e-4;
  p.t_end = 100.0;
  Engine<2> engine(p);
  engine.relax(p.relax_collisions_per_particle);
  engine.set_debug_overlap_check(5000);
  const auto start = std::chrono::steady_clock::now();
  const auto status = engine.advance_to(p.t_end, 200'000'000);  // events; pauses if exceeded
  BOOST_TEST_MESSAGE("eps = " << restitution << ", n = " << density << ", tc = 1e-4: "
                              << engine.collisions() << " collisions to t = " << engine.time()
                              << ", T = " << engine.temperature() << ", min distance "
                              << engine.min_pair_distance() << ", " << seconds_since(start)
                              << " s");
  BOOST_TEST((status == Engine<2>::Status::reached));
  BOOST_TEST(engine.min_pair_distance() >= k_min_distance);
}

// Random close packing of disks is near packing 0.84 (n = 1.07); the staggered-lattice start
// reaches n = 1.11 for N = 1000, close packing is n = 1.1547.
BOOST_DATA_TEST_CASE(dense_disks_generate_and_relax_without_overlap,
                     data::make({0.9, 1.0, 1.05, 1.1}), density) {
  Parameters p;
  p.particles = 1000;
  p.density = density;
  Engine<2> engine(p);
  BOOST_TEST(engine.min_pair_distance() > 1.0);  // generated without overlap
  engine.set_debug_overlap_check(1000);
  engine.relax(5);
  const double energy = engine.kinetic_energy();
  engine.set_collision_limit(engine.collisions() + 20'000);
  engine.advance_to(1e9);
  BOOST_TEST_MESSAGE("disks n = " << density << ": relaxed, min distance "
                                  << engine.min_pair_distance() << ", t for 2e4 collisions "
                                  << engine.time());
  BOOST_TEST(engine.min_pair_distance() >= k_min_distance);
  BOOST_TEST(engine.kinetic_energy() == energy, tt::tolerance(1e-12));
}

BOOST_DATA_TEST_CASE(dense_spheres_generate_and_relax_without_overlap, data::make({0.8, 0.9}),
                     density) {
  Parameters p;
  p.dimension = 3;
  p.particles = 1000;
  p.density = density;  // packing 0.42, 0.47 (neighbour lists)
  Engine<3> engine(p);
  BOOST_TEST(engine.min_pair_distance() > 1.0);
  engine.set_debug_overlap_check(1000);
  engine.relax(5);
  BOOST_TEST(engine.min_pair_distance() >= k_min_distance);
}

// Below close packing but above the densest start for this N: a usage error of validate() (the
// CLI exits 2 naming --density and the reachable range) before any work, not a failure of the run.
BOOST_AUTO_TEST_CASE(too_dense_start_fails_with_a_clear_message) {
  for (const auto& [dimension, density] : {std::pair{2, 1.12}, std::pair{2, 1.15},
                                           std::pair{3, 1.05}, std::pair{3, 1.4}}) {
    Parameters p;
    p.dimension = dimension;
    p.particles = 1000;
    p.density = density;
    std::string message;
    try {
      validate(p);
    } catch (const std::invalid_argument& e) {
      message = e.what();
    }
    BOOST_TEST_MESSAGE("d = " << dimension << ", n = " << density << ": " << message);
    BOOST_TEST(message.find("density: value") == 0u, message);
    BOOST_TEST(message.find(dimension == 2 ? "(0, 1.11111" : "(0, 0.99999") != std::string::npos,
               message);
    BOOST_TEST(message.find("close packing") != std::string::npos);
    BOOST_CHECK_THROW(dimension == 2 ? (void)Engine<2>(p) : (void)Engine<3>(p),
                      std::invalid_argument);
  }
  Parameters reachable;  // just below the limit: starts
  reachable.particles = 1000;
  reachable.density = 1.11;
  BOOST_CHECK_NO_THROW(validate(reachable));
}

BOOST_AUTO_TEST_CASE(particle_count_limits) {
  Parameters p;
  p.particles = 1;
  BOOST_CHECK_THROW(validate(p), std::invalid_argument);
  p.particles = 2;
  BOOST_CHECK_NO_THROW(validate(p));
  p.randomize = Randomization::flux;  // the shuffle needs two particles besides the pair
  try {
    validate(p);
    BOOST_ERROR("N = 2 with a shuffle was accepted");
  } catch (const std::invalid_argument& e) {
    BOOST_TEST(std::string(e.what()).find("particles: value 2") == 0u);
  }
  p.particles = 4;
  BOOST_CHECK_NO_THROW(validate(p));
}

// Two disks head-on in a periodic box of side L: they meet at t_1 = (d0 - 1)/(2u), and after the
// k-th collision separate at speed 2u eps^k and meet again through the boundary after a further
// (L - 2)/(2u eps^k). T = eps^(2k) T0. With eps = 0.5 and 40 collisions the temperature falls by
// 24 decades (many velocity rescalings); times and temperatures must keep full relative precision.
BOOST_AUTO_TEST_CASE(two_disks_cool_over_24_decades_exactly) {
  Parameters p;
  p.particles = 2;
  p.density = 0.02;  // L = 10
  p.restitution = 0.5;
  p.relax_collisions_per_particle = 0;
  Engine<2> engine(p);
  BOOST_REQUIRE(engine.box() == 10.0);
  engine.set_state({2, 5, 5, 5}, {1, 0, -1, 0});
  const double temperature0 = engine.temperature();  // (1 + 1) / (2 * 2) = 0.5
  BOOST_TEST(temperature0 == 0.5);
  double t_expected = 1.0, worst_t = 0, worst_T = 0;
  for (int k = 1; k <= 40; ++k) {
    while (engine.collisions() < static_cast<std::uint64_t>(k))
      BOOST_REQUIRE((engine.step() != Engine<2>::Status::stopped));
    const double T_expected = temperature0 * std::pow(0.5, 2 * k);
    worst_t = std::max(worst_t, std::fabs(engine.time() / t_expected - 1));
    worst_T = std::max(worst_T, std::fabs(engine.temperature() / T_expected - 1));
    t_expected += 8.0 / (2.0 * std::pow(0.5, k));
  }
  BOOST_TEST_MESSAGE("two disks, 40 collisions, T/T0 = " << engine.temperature() / temperature0
                                                         << ": worst relative error of t "
                                                         << worst_t << ", of T " << worst_T);
  BOOST_TEST(worst_t < 1e-12);
  BOOST_TEST(worst_T < 1e-12);
}

// A gas cooled to T/T0 < 1e-12 (flux shuffle: stays homogeneous) and then run elastically: the
// energy is conserved to 1e-12 relative at that temperature and the collision frequency is
// Enskog's at that temperature, i.e. nothing was lost to the twelve decades of cooling.
BOOST_AUTO_TEST_CASE(gas_cooled_to_1e_minus_12_keeps_relative_precision) {
  Parameters p;
  p.particles = 1000;
  p.density = 0.05;
  p.restitution = 0.5;
  p.randomize = Randomization::flux;
  Engine<2> engine(p);
  engine.relax(5);
  engine.set_min_temperature(1e-12);
  engine.set_debug_overlap_check(20000);
  BOOST_REQUIRE((engine.advance_to(1e30) == Engine<2>::Status::stopped));
  BOOST_REQUIRE((engine.stop_reason() == StopReason::min_temperature));
  const double temperature = engine.temperature();
  BOOST_TEST(temperature < 1e-12);
  // The elastic run at that temperature is a run of its own (a run's collision model is fixed),
  // started from the cooled state.
  const Snapshot cooled = engine.snapshot();
  Parameters elastic_run = p;
  elastic_run.restitution = 1.0;
  Engine<2> elastic(elastic_run);
  elastic.set_state(cooled.positions, cooled.velocities);
  elastic.set_debug_overlap_check(20000);
  BOOST_TEST(elastic.temperature() == temperature, tt::tolerance(1e-14));
  const double energy = elastic.kinetic_energy();
  const double t0 = elastic.time();
  const std::uint64_t c0 = elastic.collisions();
  elastic.set_collision_limit(c0 + 200'000);
  elastic.advance_to(1e30);
  const double collisions = static_cast<double>(elastic.collisions() - c0);
  const double omega = 2.0 * collisions / (1000.0 * (elastic.time() - t0));
  const double omega_enskog = 2.0 * p.density *
                              molchaos::theory::contact_value_g2_at_density(2, p.density) *
                              std::sqrt(3.141592653589793 * temperature);
  const double drift = std::fabs(elastic.kinetic_energy() / energy - 1);
  BOOST_TEST_MESSAGE("cooled to T = " << temperature << " at t = " << t0 << "; elastic 2e5 "
                                      << "collisions: energy drift " << drift << ", omega/omega_E "
                                      << omega / omega_enskog);
  BOOST_TEST(drift < 1e-12);
  // 2e5 collisions: the relative standard error of omega is ~0.3 %; 3 % allows the finite-N and
  // flux-shuffle corrections measured at T = 1 (< 0.1 %) many times over.
  BOOST_TEST(omega / omega_enskog == 1.0, tt::tolerance(0.03));
  BOOST_TEST(elastic.min_pair_distance() >= k_min_distance);
}

// A very dilute gas (N = 200 at n = 1e-12, box side 1.4e7): the engine's memory must scale with N,
// not with the box volume (the insertion grid alone once needed 2e14 cells). Bound: 4 kB per
// particle, some twenty times the engine's records, a thousandth of one cell per unit volume.
BOOST_AUTO_TEST_CASE(very_dilute_gas_runs_in_memory_proportional_to_n) {
  for (const int dimension : {2, 3}) {
    Parameters p;
    p.dimension = dimension;
    p.particles = 200;
    p.density = 1e-12;
    p.relax_collisions_per_particle = 0;
    std::size_t bytes = 0;
    double energy = 0, energy_after = 0;
    if (dimension == 2) {
      Engine<2> engine(p);
      energy = engine.kinetic_energy();
      BOOST_TEST((engine.advance_to(1e7) == Engine<2>::Status::reached));
      bytes = engine.memory_bytes();
      energy_after = engine.kinetic_energy();
    } else {
      Engine<3> engine(p);
      energy = engine.kinetic_energy();
      BOOST_TEST((engine.advance_to(1e5) == Engine<3>::Status::reached));
      bytes = engine.memory_bytes();
      energy_after = engine.kinetic_energy();
    }
    BOOST_TEST_MESSAGE("d = " << dimension << ", n = 1e-12, N = 200: engine holds " << bytes
                              << " bytes");
    BOOST_TEST(bytes < 200u * 4096u);
    BOOST_TEST(energy_after == energy, tt::tolerance(1e-12));
  }
}

// A cooling run over 40 decades of T (the flux shuffle keeps the gas homogeneous, N = 500,
// eps = 0.5, to t = 1e23): collisions conserve momentum only up to rounding, and without care the
// centre of mass keeps a drift that ends up holding the kinetic energy (T froze at 8.7e-35 while
// the peculiar T was 7.5e-42, and the drifting gas crossed cells for ever without colliding).
// The engine removes the drift when it matters: the run reaches t_end in some 65000 collisions,
// its T keeps following the cooling, and the drift's share of the energy stays below 1e-9.
BOOST_AUTO_TEST_CASE(cooling_over_forty_decades_keeps_the_centre_of_mass_at_rest) {
  Parameters p;
  p.particles = 500;
  p.restitution = 0.5;
  p.randomize = Randomization::flux;
  p.t_end = 1e23;
  p.max_collisions = 300000;
  Engine<2> engine(p);
  engine.relax(p.relax_collisions_per_particle);
  auto status = engine.advance_to(p.t_end, 1u << 20);
  while (status == Engine<2>::Status::paused && engine.events() < 50'000'000)
    status = engine.advance_to(p.t_end, 1u << 20);
  BOOST_REQUIRE((status == Engine<2>::Status::reached));
  const auto momentum = engine.momentum();
  double drift_energy = 0;
  for (const double component : momentum) drift_energy += component * component / (2.0 * 500);
  BOOST_TEST_MESSAGE("t = 1e23: T = " << engine.temperature() << " after " << engine.collisions()
                                      << " collisions, " << engine.events()
                                      << " events; drift's share of the energy "
                                      << drift_energy / engine.kinetic_energy());
  BOOST_TEST(engine.temperature() < 1e-40);
  BOOST_TEST(drift_energy < 1e-9 * engine.kinetic_energy());
}

// Cooling without end (t_end = 1e300): the run stops with temperature_floor when T/T0 falls
// below 1e-300, where theta^2 would overflow, instead of reporting T = 0 or running for ever.
BOOST_DATA_TEST_CASE(cooling_stops_at_the_floor_of_double_precision, data::xrange(2)) {
  Parameters p;
  p.particles = 500;
  p.restitution = 0.5;
  p.randomize = Randomization::flux;
  p.t_end = 1e300;
  p.max_collisions = 5'000'000;
  if (sample == 1) {  // spheres, whose last rescaling came 13-fold above the floor's crossing
    p.dimension = 3;
    p.particles = 300;
    p.density = 0.02;
    p.restitution = 0.8;
    p.randomize = Randomization::none;
    p.seed = 5;
    p.samples_per_decade = 4;
  }
  const RunResult r = run(p);
  BOOST_REQUIRE(!r.samples.empty());
  BOOST_TEST_MESSAGE(stop_message(r) << "; T = " << r.samples.back().temperature << " after "
                                     << r.collisions << " collisions");
  BOOST_TEST((r.stop_reason == StopReason::temperature_floor));
  BOOST_TEST(r.samples.back().temperature < k_temperature_floor);
  // At the collision that crossed the floor (one collision of 500 particles takes at most a few
  // per cent of T), not up to 16-fold below it, where the next velocity rescaling came.
  BOOST_TEST(r.samples.back().temperature > 0.9 * k_temperature_floor);
  for (std::size_t k = 0; k + 1 < r.samples.size(); ++k)
    BOOST_TEST(r.samples[k].temperature >= k_temperature_floor);
  BOOST_TEST(std::isfinite(r.samples.back().t));
}

// A gas that never collides (16 disks on separate lines, moving along them in opposite
// directions) only crosses cells: with a collision limit, the run ends at the event bound that
// limit implies (stop reason max_events) instead of running to t_end.
BOOST_AUTO_TEST_CASE(a_gas_that_stops_colliding_ends_at_the_event_bound) {
  Parameters p;
  p.particles = 16;
  p.density = 0.05;
  p.t_end = 1e12;
  p.relax_collisions_per_particle = 0;
  Engine<2> engine(p);
  std::vector<double> positions, velocities;
  for (int k = 0; k < 16; ++k) {
    positions.insert(positions.end(), {0.5 + 1.0 * k, 0.5 + 1.1 * k});
    velocities.insert(velocities.end(), {k % 2 == 0 ? 1.0 : -1.0, 0.0});
  }
  engine.set_state(positions, velocities);
  engine.set_collision_limit(10);
  BOOST_REQUIRE(engine.event_limit() > 0u);
  BOOST_TEST((engine.advance_to(p.t_end) == Engine<2>::Status::stopped));
  BOOST_TEST((engine.stop_reason() == StopReason::max_events));
  BOOST_TEST(engine.collisions() == 0u);
  BOOST_TEST(engine.events() == engine.event_limit());
  BOOST_TEST(engine.time() < p.t_end);
}

// The event bound leaves ordinary runs alone: dilute and dense, 2D and 3D (cells and neighbour
// lists), with and without a shuffle, each stops at max_collisions, using a small fraction of
// the events the bound allows.
BOOST_AUTO_TEST_CASE(the_event_bound_leaves_ordinary_runs_alone) {
  struct Case {
    int dimension;
    double density;
    Randomization shuffle;
  };
  for (const Case c : {Case{2, 1e-4, Randomization::none}, Case{2, 0.05, Randomization::paper},
                       Case{2, 0.7, Randomization::flux}, Case{3, 0.1, Randomization::none},
                       Case{3, 0.6, Randomization::paper}}) {
    Parameters p;
    p.dimension = c.dimension;
    p.particles = 1000;
    p.density = c.density;
    p.randomize = c.shuffle;
    p.restitution = 0.9;
    p.t_end = 1e12;
    p.max_collisions = 20000;
    const RunResult r = run(p);
    const double allowed_per_collision =
        static_cast<double>(c.dimension == 2 ? Engine<2>(p).event_limit()
                                             : Engine<3>(p).event_limit()) /
        static_cast<double>(p.max_collisions);
    const double used = static_cast<double>(r.events) / static_cast<double>(r.collisions);
    BOOST_TEST_MESSAGE("d = " << c.dimension << ", n = " << c.density << ", " << to_string(c.shuffle)
                              << ": " << used << " events per collision, "
                              << used / allowed_per_collision << " of the bound");
    BOOST_TEST((r.stop_reason == StopReason::max_collisions));
    BOOST_TEST(used < 0.1 * allowed_per_collision);
  }
}
