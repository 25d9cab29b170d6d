// Unit tests of molchaos::sim: the collision rule, the shuffles, the random numbers, parameter
// validation, the sample grid and the CSV format.
#define BOOST_TEST_MODULE sim_unit
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <vector>

#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/collision.hpp"
#include "molchaos/sim/csv.hpp"
#include "molchaos/sim/event_calendar.hpp"
#include "molchaos/sim/rng.hpp"
#include "molchaos/sim/run.hpp"

using namespace molchaos::sim;
constexpr double pi = std::numbers::pi;

BOOST_AUTO_TEST_CASE(collision_rule_energy_loss_and_momentum) {
  // A head-on-ish collision in 3D with an arbitrary normal: the energy lost is (1-eps^2)/4 (g.e)^2
  // and momentum is conserved, to rounding.
  const double eps = 0.7;
  double vi[3] = {0.3, -1.1, 0.4}, vj[3] = {-0.8, 0.5, 0.2};
  double e[3] = {-1.0, 0.5, -0.25};
  const double norm = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  for (double& x : e) x /= norm;
  double energy0 = 0, p0[3];
  for (int a = 0; a < 3; ++a) {
    energy0 += 0.5 * (vi[a] * vi[a] + vj[a] * vj[a]);
    p0[a] = vi[a] + vj[a];
  }
  double gn = 0;
  for (int a = 0; a < 3; ++a) gn += (vi[a] - vj[a]) * e[a];
  BOOST_TEST(gn < 0);
  const double reported = ConstantRestitution{eps}.apply<3>(vi, vj, e, gn, false);
  double energy1 = 0, gn_after = 0;
  for (int a = 0; a < 3; ++a) {
    energy1 += 0.5 * (vi[a] * vi[a] + vj[a] * vj[a]);
    BOOST_TEST(vi[a] + vj[a] == p0[a], boost::test_tools::tolerance(1e-15));
    gn_after += (vi[a] - vj[a]) * e[a];
  }
  BOOST_TEST(energy0 - energy1 == (1 - eps * eps) / 4 * gn * gn,
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(gn_after == -eps * gn, boost::test_tools::tolerance(1e-14));
  // The rule reports the energy it removed: the same, to the rounding of the energies.
  BOOST_TEST(reported == energy0 - energy1, boost::test_tools::tolerance(1e-14));
  // Made elastic (TC model): no loss, the normal velocity reversed.
  double wi[3] = {0.3, -1.1, 0.4}, wj[3] = {-0.8, 0.5, 0.2};
  BOOST_TEST(ConstantRestitution{eps}.apply<3>(wi, wj, e, gn, true) == 0.0);
  double reversed = 0;
  for (int a = 0; a < 3; ++a) reversed += (wi[a] - wj[a]) * e[a];
  BOOST_TEST(reversed == -gn, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(tc_model_is_elastic_only_within_its_duration) {
  BOOST_TEST(!TcModel{}.apply(0.0));  // off
  BOOST_TEST(!TcModel{0.0}.apply(1e-300));
  BOOST_TEST(TcModel{1e-4}.apply(0.99e-4));
  BOOST_TEST(!TcModel{1e-4}.apply(1e-4));
  BOOST_TEST(!TcModel{1e-4}.apply(std::numeric_limits<double>::infinity()));  // never collided
}

BOOST_AUTO_TEST_CASE(exchange_makes_the_pair_separate_and_permutes_velocities) {
  Rng rng(7);
  for (int trial = 0; trial < 1000; ++trial) {
    std::vector<double> v(8);
    for (double& x : v) x = rng.normal();
    const double angle = 2 * pi * rng.uniform();
    const double e[2] = {std::cos(angle), std::sin(angle)};
    const std::vector<double> before = v;
    exchange_velocities<2>(&v[0], &v[2], &v[4], &v[6], e);
    const double separation = (v[0] - v[2]) * e[0] + (v[1] - v[3]) * e[1];
    BOOST_TEST(separation >= 0);
    // i, j carry the old k, l velocities (in some order); k, l carry the old i, j ones.
    const bool straight = v[0] == before[4] && v[2] == before[6];
    const bool swapped = v[0] == before[6] && v[2] == before[4];
    BOOST_TEST((straight || swapped));
    BOOST_TEST(
        ((v[4] == before[0] && v[6] == before[2]) || (v[6] == before[0] && v[4] == before[2])));
  }
}

BOOST_AUTO_TEST_CASE(flux_shuffle_weights_pairs_by_normal_speed) {
  // Velocities from a Maxwellian with T = 1: g.e ~ N(0, 2). Uniform pairs give <|g.e|> =
  // sqrt(2) sqrt(2/pi) = 2/sqrt(pi); flux-weighted pairs <|g.e|> = <g^2>/<|g|> = sqrt(pi).
  Rng rng(11);
  const std::int32_t n = 20000;
  std::vector<double> v(2 * n);
  for (double& x : v) x = rng.normal();
  const double e[2] = {0.6, 0.8};
  const int draws = 200000;
  auto mean_and_error = [&](auto pick) {
    double sum = 0, sum2 = 0;
    for (int s = 0; s < draws; ++s) {
      const auto [k, l] = pick();
      const double g =
          std::fabs((v[2 * k] - v[2 * l]) * e[0] + (v[2 * k + 1] - v[2 * l + 1]) * e[1]);
      sum += g;
      sum2 += g * g;
    }
    const double mean = sum / draws;
    return std::pair{mean, std::sqrt((sum2 / draws - mean * mean) / draws)};
  };
  const auto velocity = [&](std::int32_t k) { return &v[2 * k]; };
  const auto [flux_mean, flux_error] =
      mean_and_error([&] { return FluxShuffle{}.pick<2>(velocity, n, 0, 1, e, 1.0, rng); });
  const auto [uniform_mean, uniform_error] =
      mean_and_error([&] { return PaperShuffle{}.pick<2>(velocity, n, 0, 1, e, 1.0, rng); });
  BOOST_TEST_MESSAGE("flux <|g.e|> = " << flux_mean << " +- " << flux_error
                                       << " (expected sqrt(pi) = " << std::sqrt(pi) << ")");
  // The finite sample of 20000 velocities has its own temperature, so allow its sampling error too.
  BOOST_TEST(std::fabs(flux_mean - std::sqrt(pi)) < 3 * flux_error + 0.02);
  BOOST_TEST(std::fabs(uniform_mean - 2 / std::sqrt(pi)) < 3 * uniform_error + 0.02);
}

BOOST_AUTO_TEST_CASE(rng_is_reproducible_and_normal) {
  Rng a(42), b(42);
  for (int i = 0; i < 100; ++i) BOOST_TEST(a.next() == b.next());
  Rng rng(3);
  const int count = 400000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < count; ++i) {
    const double x = rng.normal();
    sum += x;
    sum2 += x * x;
  }
  // Standard errors: 1/sqrt(count) for the mean, sqrt(2/count) for the variance.
  BOOST_TEST(std::fabs(sum / count) < 3 / std::sqrt(double(count)));
  BOOST_TEST(std::fabs(sum2 / count - 1) < 3 * std::sqrt(2.0 / count));
}

BOOST_AUTO_TEST_CASE(validation_names_the_field) {
  auto message = [](Parameters p) {
    try {
      validate(p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  Parameters p;
  BOOST_TEST(message(p).empty());
  p.density = 1.2;
  BOOST_TEST(message(p).rfind("density: value 1.2 is outside the allowed range", 0) == 0);
  p.dimension = 3;  // below close packing in 3D, but above the densest start for N = 5000
  BOOST_TEST(message(p).rfind("density: value 1.2 is outside the allowed range (0, 0.857", 0) == 0);
  p.density = 0.8;
  BOOST_TEST(message(p).empty());
  p = {};
  p.restitution = 0;
  BOOST_TEST(message(p).rfind("restitution:", 0) == 0);
  p = {};
  p.particles = 5;
  p.density = 0.8;
  BOOST_TEST(message(p).rfind("particles:", 0) == 0);  // box below 3 sigma
  p = {};
  p.snapshot_times = {2000.0};
  BOOST_TEST(message(p).rfind("snapshot_times:", 0) == 0);
}

BOOST_AUTO_TEST_CASE(randomization_names_round_trip) {
  for (auto mode : {Randomization::none, Randomization::paper, Randomization::flux})
    BOOST_TEST((parse_randomization(to_string(mode)) == mode));
  BOOST_TEST(!parse_randomization("shuffle").has_value());
}

BOOST_AUTO_TEST_CASE(sample_grid_is_log_spaced) {
  Parameters p;
  p.t_first_sample = 0.01;
  p.samples_per_decade = 10;
  p.t_end = 100;
  const auto t = sample_times(p);
  BOOST_TEST(t.front() == 0.0);
  BOOST_TEST(t.back() == 100.0);
  BOOST_TEST(t.size() == 1u + 40u + 1u);
  BOOST_TEST(t[11] == 0.1, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(enskog_contact_values) {
  // Henderson (disks) and Carnahan-Starling (spheres) at eta = 0.1 and 0.4.
  const double n2 = 0.1 * 4 / pi, n3 = 0.4 * 6 / pi;
  BOOST_TEST(contact_value_g2(2, n2) == (1 - 0.7 / 16) / 0.81, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(contact_value_g2(3, n3) == 0.8 / 0.216, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(enskog_collision_frequency(2, n2, 4.0) ==
                 2 * n2 * contact_value_g2(2, n2) * std::sqrt(4 * pi),
             boost::test_tools::tolerance(1e-14));
}

namespace {
RunResult small_result() {
  RunResult r;
  r.parameters.restitution = 0.93;
  r.parameters.randomize = Randomization::flux;
  r.parameters.contact_statistics = true;
  r.parameters.snapshot_times = {1.5, 2.0 / 3.0};
  r.version = "test";
  r.stop_reason = StopReason::t_end;
  r.collisions = 12;
  r.events = 40;
  for (int k = 0; k < 3; ++k) {
    Sample s;
    s.t = 0.1 * k + 1.0 / 3.0;
    s.temperature = 1.0 / (1 + k);
    s.a2 = -0.01 * k;
    s.collisions = 4u * k;
    s.events = 13u * k;
    s.velocity_mode = 1.0 / 7.0;
    s.density_mode = 0.9;
    s.contacts = {5, 0.1, 0.2, 0.3, 0.4, 1e-300};
    s.contacts.impact_histogram[static_cast<std::size_t>(k)] = 7u + k;
    r.samples.push_back(s);
  }
  return r;
}
}  // namespace

BOOST_AUTO_TEST_CASE(csv_round_trip_is_exact) {
  const RunResult r = small_result();
  std::stringstream file;
  write_csv(r, file);
  const RunResult back = read_csv(file);
  BOOST_TEST(back.parameters.restitution == 0.93);
  BOOST_TEST((back.parameters.randomize == Randomization::flux));
  BOOST_TEST(back.parameters.snapshot_times == r.parameters.snapshot_times);
  BOOST_TEST(back.samples.size() == 3u);
  BOOST_TEST(back.samples[2].t == r.samples[2].t);
  BOOST_TEST(back.samples[1].temperature == 0.5);
  BOOST_TEST(back.samples[2].contacts.sum_g2 == 1e-300);
  BOOST_TEST(back.samples[2].contacts.impact_histogram == r.samples[2].contacts.impact_histogram);
  std::stringstream again;
  write_csv(back, again);
  std::stringstream first;
  write_csv(r, first);
  BOOST_TEST(again.str() == first.str());
}

BOOST_AUTO_TEST_CASE(csv_reader_rejects_truncated_and_corrupt_files) {
  std::stringstream file;
  write_csv(small_result(), file);
  const std::string text = file.str();
  auto rejects = [](const std::string& content) {
    std::istringstream in(content);
    try {
      read_csv(in);
    } catch (const std::runtime_error&) {
      return true;
    }
    return false;
  };
  BOOST_TEST(!rejects(text));
  BOOST_TEST(rejects(text.substr(0, text.size() - 5)));  // cut inside the last row
  const auto last_row = text.rfind('\n', text.size() - 2);
  BOOST_TEST(rejects(text.substr(0, last_row + 1)));  // a whole row missing
  BOOST_TEST(rejects(""));
  std::string bad = text;
  bad.replace(bad.find("0.93"), 4, "0.9x");
  BOOST_TEST(rejects(bad));
}

BOOST_AUTO_TEST_CASE(event_calendar_always_yields_the_earliest_event) {
  // Random schedule/reschedule/pop sequences against a brute-force minimum, including events far
  // beyond the bucket window, infinite times and ties; through all of them the calendar stays
  // well formed, as a restored checkpoint's must be.
  Rng rng(5);
  const std::int32_t n = 300;
  EventCalendar calendar;
  calendar.reset(n, 0.0, 0.01, 4 * n);
  std::vector<double> times(n);
  double now = 0;
  for (std::int32_t i = 0; i < n; ++i) {
    times[i] = now + (i % 17 == 0 ? 1e6 : rng.uniform());
    calendar.update(i, times[i]);
  }
  BOOST_TEST(calendar.well_formed(n));
  BOOST_TEST(!calendar.well_formed(n + 1));
  for (int step = 0; step < 100000; ++step) {
    if (step % 1000 == 0) BOOST_REQUIRE(calendar.well_formed(n));
    const auto [t, i] = calendar.top();
    double expected = std::numeric_limits<double>::infinity();
    for (double x : times) expected = std::min(expected, x);
    BOOST_REQUIRE(t == expected);
    BOOST_REQUIRE(times[i] == t);
    now = t;
    // The popped particle gets a new event; sometimes another particle is rescheduled too.
    const double u = rng.uniform();
    times[i] = u < 0.01   ? std::numeric_limits<double>::infinity()
               : u < 0.05 ? now + 1e3 * rng.uniform()
               : u < 0.10 ? now
                          : now + rng.uniform();
    calendar.update(i, times[i]);
    if (rng.uniform() < 0.3) {
      const auto k = static_cast<std::int32_t>(rng.below(n));
      times[k] = now + 0.5 * rng.uniform();
      calendar.update(k, times[k]);
    }
  }
}

// Files staged together appear together: with the second's name taken by a directory before the
// commit, the first keeps its earlier content, and no temporary is left once the set is dropped.
BOOST_AUTO_TEST_CASE(staged_files_appear_together_or_not_at_all) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "molchaos_test_staged_files";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string first = (dir / "a.csv").string(), second = (dir / "b.csv").string();
  std::ofstream(first) << "earlier\n";
  {
    StagedFiles files;
    files.write(first, [](std::ostream& out) { out << "new\n"; });
    files.write(second, [](std::ostream& out) { out << "new\n"; });
    fs::create_directories(second);  // the name taken meanwhile
    BOOST_CHECK_THROW(files.commit(), std::runtime_error);
  }
  std::string text;
  std::getline(std::ifstream(first), text);
  BOOST_TEST(text == "earlier");
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  BOOST_TEST(entries == 2);  // a.csv and the directory b.csv: no temporary
  fs::remove_all(dir);
}
