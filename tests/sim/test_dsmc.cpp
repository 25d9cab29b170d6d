// The DSMC method against exact results: the contact-vector law, the elastic gas's stationary
// (microcanonical Maxwell) state, Enskog's collision frequency, the molecular-chaos moments of the
// colliding pairs, the initial cooling rate μ2(a2 = 0); the long-time a2 against the first Sonine
// approximation (reported); reproducibility and bad input. Statistical claims are tested as a
// whole (Hotelling's T² over all quantities, or χ²) with a false-alarm probability of 1e-3.
#define BOOST_TEST_MODULE sim_dsmc
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_sf_gamma.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstring>
#include <ctime>
#include <numbers>
#include <string>
#include <vector>

#include "molchaos/sim/dsmc.hpp"
#include "molchaos/sim/dsmc_contact.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/sonine.hpp"
#include "molchaos/validation/analysis.hpp"
#include "molchaos/validation/ensemble.hpp"

using namespace molchaos::sim;

namespace {

constexpr double k_false_alarm = 1e-3;

struct MeanError {
  double mean = 0, error = 0;
};

MeanError mean_error(const std::vector<double>& x) {
  MeanError m;
  for (double v : x) m.mean += v;
  m.mean /= static_cast<double>(x.size());
  double ss = 0;
  for (double v : x) ss += (v - m.mean) * (v - m.mean);
  const double n = static_cast<double>(x.size());
  m.error = std::sqrt(ss / (n - 1) / n);
  return m;
}

// Hotelling's T² test that the mean of p correlated quantities, measured once per independent
// run (rows), equals `expected`: F = (R − p)/(p (R − 1)) T² follows F(p, R − p). Returns the
// probability of a larger F.
double hotelling_p_value(const std::vector<std::vector<double>>& rows,
                         const std::vector<double>& expected) {
  const std::size_t r = rows.size(), p = expected.size();
  std::vector<double> mean(p, 0.0);
  for (const auto& row : rows)
    for (std::size_t a = 0; a < p; ++a) mean[a] += row[a] / static_cast<double>(r);
  gsl_matrix* cov = gsl_matrix_calloc(p, p);
  for (const auto& row : rows)
    for (std::size_t a = 0; a < p; ++a)
      for (std::size_t b = 0; b < p; ++b)
        *gsl_matrix_ptr(cov, a, b) +=
            (row[a] - mean[a]) * (row[b] - mean[b]) / static_cast<double>((r - 1) * r);
  gsl_vector* diff = gsl_vector_alloc(p);
  gsl_vector* solved = gsl_vector_alloc(p);
  for (std::size_t a = 0; a < p; ++a) gsl_vector_set(diff, a, mean[a] - expected[a]);
  gsl_linalg_cholesky_decomp1(cov);
  gsl_linalg_cholesky_solve(cov, diff, solved);
  double t2 = 0;
  for (std::size_t a = 0; a < p; ++a) t2 += gsl_vector_get(diff, a) * gsl_vector_get(solved, a);
  gsl_matrix_free(cov);
  gsl_vector_free(diff);
  gsl_vector_free(solved);
  const double rd = static_cast<double>(r), pd = static_cast<double>(p);
  const double f = (rd - pd) / (pd * (rd - 1)) * t2;
  BOOST_TEST_MESSAGE("Hotelling T^2 = " << t2 << " over " << p << " quantities, " << r
                                        << " runs: F = " << f
                                        << ", p = " << gsl_cdf_fdist_Q(f, pd, rd - pd));
  return gsl_cdf_fdist_Q(f, pd, rd - pd);
}

Parameters gas_parameters(int d, std::int64_t particles, double restitution, std::uint64_t seed) {
  Parameters p;
  p.dimension = d;
  p.particles = particles;
  p.density = d == 2 ? 0.05 : 0.6 / std::numbers::pi;
  p.restitution = restitution;
  p.seed = seed;
  p.t_end = 1e300;
  p.relax_collisions_per_particle = 0;  // DSMC does no relaxation
  return p;
}

// The elastic gas started as run_dsmc starts it is uniform on the sphere Σv² = N d T in the
// zero-momentum subspace of dimension m = d(N − 1), and the elastic dynamics keep that measure.
// There |v1|² = (1 − 1/N) N d T · B and |v1 − v2|² = 2 N d T · B with B ~ Beta(d/2, (m − d)/2),
// which gives the exact finite-N moments below (Maxwell's values as N → ∞).
struct Microcanonical {
  int d;
  double m;
  explicit Microcanonical(int dimension, double particles)
      : d(dimension), m(dimension * (particles - 1)) {}
  // a2 = d/(d+2) <v⁴>/<v²>² − 1 = −2/(m + 2).
  [[nodiscard]] double a2() const { return -2.0 / (m + 2.0); }
  // <c⁶> with c = v/√(2T): d(d+2)(d+4)/8 · m²/((m+2)(m+4)).
  [[nodiscard]] double c6() const {
    return d * (d + 2.0) * (d + 4.0) / 8.0 * m * m / ((m + 2.0) * (m + 4.0));
  }
  // <|g|> over Maxwell's <|g|> = √(2T) √2 Γ((d+1)/2)/Γ(d/2).
  [[nodiscard]] double mean_speed_ratio(double particles) const {
    const double alpha = d / 2.0, total = m / 2.0;
    const double mean_sqrt_b = std::exp(gsl_sf_lngamma(alpha + 0.5) + gsl_sf_lngamma(total) -
                                        gsl_sf_lngamma(alpha) - gsl_sf_lngamma(total + 0.5));
    const double exact = std::sqrt(2.0 * particles * d) * mean_sqrt_b;  // T = 1
    const double maxwell = 2.0 * std::exp(gsl_sf_lngamma((d + 1) / 2.0) - gsl_sf_lngamma(d / 2.0));
    return exact / maxwell;
  }
};

// Per run of an elastic gas: ω/ω_exact, a2, <c⁶>, and the contact moments of the colliding pairs.
template <int D>
std::vector<double> elastic_run(std::int64_t particles, std::uint64_t seed,
                                double collisions_per_particle, int samples) {
  Parameters p = gas_parameters(D, particles, 1.0, seed);
  p.contact_statistics = true;
  DsmcGas<D> gas(p, contact_value_g2(D, p.density));
  const double n = static_cast<double>(particles);
  const double omega_e = enskog_collision_frequency(D, p.density, 1.0);
  const double t_end = collisions_per_particle / omega_e;
  double a2 = 0, c6 = 0;
  ContactMoments sum;
  for (int k = 1; k <= samples; ++k) {
    gas.advance_to(t_end * k / samples);
    const Sample s = gas.sample();
    a2 += s.a2 / samples;
    const std::vector<double> v = gas.velocities();
    double m2 = 0, m6 = 0;
    for (std::size_t i = 0; i < v.size(); i += D) {
      double v2 = 0;
      for (int a = 0; a < D; ++a) v2 += v[i + a] * v[i + a];
      m2 += v2;
      m6 += v2 * v2 * v2;
    }
    const double two_t = 2.0 * m2 / (n * D);
    c6 += m6 / n / (two_t * two_t * two_t) / samples;
    sum.count += s.contacts.count;
    sum.sum_c1e_c2e += s.contacts.sum_c1e_c2e;
    sum.sum_c1_dot_c2 += s.contacts.sum_c1_dot_c2;
    sum.sum_gn2 += s.contacts.sum_gn2;
    sum.sum_abs_gn += s.contacts.sum_abs_gn;
    sum.sum_g2 += s.contacts.sum_g2;
  }
  const double omega = 2.0 * static_cast<double>(gas.collisions()) / (n * t_end);
  const double c = static_cast<double>(sum.count);
  const Microcanonical exact(D, n);
  return {omega / (omega_e * exact.mean_speed_ratio(n)),
          a2,
          c6,
          sum.sum_c1e_c2e / c,
          sum.sum_c1_dot_c2 / c,
          sum.sum_gn2 / c,
          sum.sum_abs_gn / c,
          sum.sum_g2 / c};
}

template <int D>
void check_elastic_gas() {
  constexpr std::int64_t particles = 10000;
  constexpr int runs = 30;
  const Microcanonical exact(D, particles);
  // Over colliding pairs, c = v/√(2T): C = (c1 + c2)/2 has components N(0, 1/4) independent of
  // g = c1 − c2 (components N(0, 1)); the collision weight Θ(−g·e)|g·e| acts only on x = g·e,
  // giving <x²> = 2, <|x|> = √(π/2), <g²> = 2 + (d − 1). Hence <(c1·e)(c2·e)> = <(C·e)²> − <x²>/4
  // = −1/4, <c1·c2> = <C²> − <g²>/4 = d/4 − (d + 1)/4 = −1/4, and the dyad <3(c1·e)(c2·e) − c1·c2>
  // = −1/2. Finite N shifts these by O(1/N) = 1e-4, below the standard errors (~4e-4). The
  // frequency is the exact one of N − 1 partners at the density (N − 1)/V (dsmc.hpp).
  const std::vector<double> expected{
      (particles - 1.0) / particles,   exact.a2(), exact.c6(), -0.25, -0.25, 2.0,
      std::sqrt(std::numbers::pi / 2), D + 1.0};
  const char* names[] = {"omega/omega_exact", "a2",          "<c^6>",     "<(c1.e)(c2.e)>",
                         "<c1.c2>",           "<(c12.e)^2>", "<|c12.e|>", "<c12^2>"};
  std::vector<std::vector<double>> rows;
  std::vector<double> dyad;
  for (int r = 0; r < runs; ++r) {
    rows.push_back(elastic_run<D>(particles, 1000 + r, 10.0, 5));
    dyad.push_back(3 * rows.back()[3] - rows.back()[4]);
  }
  for (std::size_t q = 0; q < expected.size(); ++q) {
    std::vector<double> column;
    for (const auto& row : rows) column.push_back(row[q]);
    const MeanError m = mean_error(column);
    BOOST_TEST_MESSAGE("d = " << D << " elastic " << names[q] << ": " << m.mean << " +- " << m.error
                              << ", exact " << expected[q] << " ("
                              << (m.mean - expected[q]) / m.error << " SE)");
  }
  const MeanError b = mean_error(dyad);
  BOOST_TEST_MESSAGE("d = " << D << " elastic <B> = " << b.mean << " +- " << b.error
                            << " (molecular chaos: -1/2; " << (b.mean + 0.5) / b.error << " SE)");
  BOOST_TEST_MESSAGE(
      "d = " << D << " Maxwell limits: a2 = 0, <c^6> = " << D * (D + 2) * (D + 4) / 8.0
             << "; omega_exact/omega_Enskog = " << exact.mean_speed_ratio(particles));
  BOOST_TEST(hotelling_p_value(rows, expected) > k_false_alarm);
}

}  // namespace

BOOST_AUTO_TEST_CASE(contact_value_is_the_theory_librarys) {
  for (int d : {2, 3})
    for (double n : {0.01, 0.05, 0.1, 0.5, 0.9}) {
      const double sim_g2 = contact_value_g2(d, n);
      const double theory_g2 = molchaos::theory::contact_value_g2_at_density(d, n);
      BOOST_TEST(std::fabs(sim_g2 - theory_g2) <= 1e-14 * theory_g2);
    }
}

// e has density Θ(−g·e)|g·e|/β_d: the impact parameter is flat on [−1, 1] in 2D, sin²θ is
// uniform on [0, 1] in 3D and the azimuth uniform; χ² over 20 bins each, all in one χ².
BOOST_AUTO_TEST_CASE(contact_direction_is_flux_weighted) {
  constexpr int draws = 200000, bins = 20;
  Rng rng(7);
  double chi2 = 0;
  int dof = 0;
  auto add_histogram = [&](const std::vector<int>& count) {
    const double expected = static_cast<double>(draws) / bins;
    for (int c : count) chi2 += (c - expected) * (c - expected) / expected;
    dof += bins - 1;
  };
  double worst_norm = 0;
  bool always_approaching = true;
  {
    std::vector<int> impact(bins, 0);
    for (int k = 0; k < draws; ++k) {
      const double g[2] = {rng.normal(), rng.normal()};
      const double norm = std::hypot(g[0], g[1]);
      double e[2];
      draw_contact_direction<2>(g, norm, rng, e);
      worst_norm = std::max(worst_norm, std::fabs(std::hypot(e[0], e[1]) - 1));
      always_approaching = always_approaching && g[0] * e[0] + g[1] * e[1] < 0;
      const double b = (-g[1] * e[0] + g[0] * e[1]) / norm;  // e along (−ĝ_y, ĝ_x)
      ++impact[std::min(bins - 1, static_cast<int>((b + 1) / 2 * bins))];
    }
    add_histogram(impact);
  }
  {
    std::vector<int> sin2(bins, 0), azimuth(bins, 0);
    for (int k = 0; k < draws; ++k) {
      const double g[3] = {rng.normal(), rng.normal(), rng.normal()};
      const double norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
      double e[3];
      draw_contact_direction<3>(g, norm, rng, e);
      const double length = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
      worst_norm = std::max(worst_norm, std::fabs(length - 1));
      const double cosine = (g[0] * e[0] + g[1] * e[1] + g[2] * e[2]) / norm;
      always_approaching = always_approaching && cosine < 0;
      ++sin2[std::min(bins - 1, static_cast<int>((1 - cosine * cosine) * bins))];
      // Azimuth with g along z (a fixed frame): the same sampler, g = (0, 0, |g|).
      const double gz[3] = {0, 0, norm};
      draw_contact_direction<3>(gz, norm, rng, e);
      const double phi = std::atan2(e[1], e[0]);
      ++azimuth[std::min(
          bins - 1, static_cast<int>((phi + std::numbers::pi) / (2 * std::numbers::pi) * bins))];
    }
    add_histogram(sin2);
    add_histogram(azimuth);
  }
  const double p = gsl_cdf_chisq_Q(chi2, dof);
  BOOST_TEST_MESSAGE("impact parameter (2D), sin^2 theta and azimuth (3D): chi2 = "
                     << chi2 << " for " << dof << " dof, p = " << p);
  BOOST_TEST(worst_norm < 1e-14);
  BOOST_TEST(always_approaching);
  BOOST_TEST(p > k_false_alarm);
}

BOOST_AUTO_TEST_CASE(elastic_gas_is_maxwellian_with_enskogs_frequency_and_chaotic_contacts_2d) {
  check_elastic_gas<2>();
}

BOOST_AUTO_TEST_CASE(elastic_gas_is_maxwellian_with_enskogs_frequency_and_chaotic_contacts_3d) {
  check_elastic_gas<3>();
}

// A pair of the N particles collides at the rate of a pair of the MD's gas in the same volume
// (each particle meets N − 1 partners at the density (N − 1)/V): at N = 20 the elastic frequency
// is (N − 1)/N = 0.95 of n g2 β_d ⟨|g|⟩, with ⟨|g|⟩ that of the N-particle state (Microcanonical).
// Was n g2 β_d ⟨|g|⟩ itself, 1/N = 5 % more collisions than the MD gas of the same N, and an A
// 5 % below the MD's. 40 runs of 500 collisions per particle: SE about 0.2 %.
BOOST_AUTO_TEST_CASE(small_gas_collides_as_often_as_the_md_gas_of_its_size) {
  constexpr std::int64_t particles = 20;
  std::vector<double> ratio;
  for (int r = 0; r < 40; ++r) ratio.push_back(elastic_run<2>(particles, 300 + r, 500.0, 1)[0]);
  const MeanError m = mean_error(ratio);
  const double expected = (particles - 1.0) / particles;
  BOOST_TEST_MESSAGE("N = 20: omega/omega_exact = " << m.mean << " +- " << m.error << ", expected "
                                                    << expected);
  BOOST_TEST(std::abs(m.mean - expected) < 3.3 * m.error);  // two-sided false alarm 1e-3
}

// From the Maxwell start, the energy lost per unit time is N g2 n √2 μ2(a2 = 0, b = 0) at T0 = 1
// (cooling.hpp: dT/dt = −(2/d) g2 n √(2T) μ2 T). Each run lasts t1, about 50 collisions among
// N = 20000 particles, and gives μ2 = d (1 − T(t1)) / (2 t1 g2 n √2), exact in expectation up to
// the drift of the rate within t1: T^{3/2} falls by 1.5 (1 − ε²) K/(N d) ≤ 7e-4 relative on
// average (a2 grows even less), a tenth of the standard error of 1000 runs (~0.6 %).
BOOST_AUTO_TEST_CASE(initial_cooling_rate_is_mu2_at_a2_zero) {
  constexpr double restitution = 0.8, expected_collisions = 50;
  constexpr std::int64_t particles = 20000;
  constexpr int runs = 1000;
  double chi2 = 0;
  for (int d : {2, 3}) {
    std::vector<double> mu2;
    const Parameters base = gas_parameters(d, particles, restitution, 0);
    const double g2 = contact_value_g2(d, base.density);
    const double t1 =
        2.0 * expected_collisions / (particles * enskog_collision_frequency(d, base.density, 1.0));
    for (int r = 0; r < runs; ++r) {
      Parameters p = base;
      p.seed = 5000 + r;
      double temperature;
      if (d == 2) {
        DsmcGas<2> gas(p, g2);
        gas.advance_to(t1);
        temperature = gas.sample().temperature;
      } else {
        DsmcGas<3> gas(p, g2);
        gas.advance_to(t1);
        temperature = gas.sample().temperature;
      }
      mu2.push_back(d * (1 - temperature) / (2 * t1 * g2 * p.density * std::numbers::sqrt2));
    }
    const MeanError m = mean_error(mu2);
    const auto theory = molchaos::theory::mu2(d, restitution, 0.0, 0.0);
    const double deviation = (m.mean - theory.value) / std::hypot(m.error, theory.error);
    BOOST_TEST_MESSAGE("d = " << d << ", eps = " << restitution << ": mu2 from the first "
                              << expected_collisions << " collisions = " << m.mean << " +- "
                              << m.error << ", theory mu2(a2 = 0) = " << theory.value << " +- "
                              << theory.error << " (" << deviation << " SE)");
    chi2 += deviation * deviation;
  }
  BOOST_TEST(gsl_cdf_chisq_Q(chi2, 2) > k_false_alarm);
}

// The scaled homogeneous cooling state's a2 against the first Sonine approximation (van Noije &
// Ernst; the paper's eq. a2linD for d = 2). Not asserted equal (the first Sonine approximation is
// an approximation): the difference is reported. Asserted: the DSMC a2 is resolved (error below a
// fifth of |a2|) and has the theory's sign, i.e. the HCS is measurably non-Maxwellian.
BOOST_AUTO_TEST_CASE(cooling_state_a2_against_first_sonine) {
  constexpr std::int64_t particles = 10000;
  constexpr int runs = 8;
  for (int d : {2, 3})
    for (double restitution : {0.8, 0.5}) {
      std::vector<double> a2_runs;
      for (int r = 0; r < runs; ++r) {
        const Parameters p = gas_parameters(d, particles, restitution, 300 + r);
        const double g2 = contact_value_g2(d, p.density);
        double a2 = 0;
        int count = 0;
        auto step = [&](auto& gas) {
          // 2 collisions per particle per step at the current temperature; average from 20 on.
          for (int k = 1; k <= 40; ++k) {
            const double omega = enskog_collision_frequency(d, p.density, gas.temperature());
            gas.advance_to(gas.time() + 2.0 / omega);
            const Sample s = gas.sample();
            if (k > 10) {
              a2 += s.a2;
              ++count;
            }
          }
        };
        if (d == 2) {
          DsmcGas<2> gas(p, g2);
          step(gas);
        } else {
          DsmcGas<3> gas(p, g2);
          step(gas);
        }
        a2_runs.push_back(a2 / count);
      }
      const MeanError m = mean_error(a2_runs);
      const double sonine = molchaos::theory::a2_first_sonine(d, restitution);
      BOOST_TEST_MESSAGE("d = " << d << ", eps = " << restitution << ": HCS a2 (DSMC, N = "
                                << particles << ", " << runs << " runs) = " << m.mean << " +- "
                                << m.error << "; first Sonine " << sonine << "; difference "
                                << m.mean - sonine << " (" << (m.mean - sonine) / m.error << " SE, "
                                << 100 * (m.mean - sonine) / std::fabs(sonine) << " %)");
      BOOST_TEST(m.error < 0.2 * std::fabs(m.mean));
      BOOST_TEST(m.mean * sonine > 0);
    }
}

BOOST_AUTO_TEST_CASE(same_seed_same_bytes_and_the_md_sample_grid) {
  Parameters p = gas_parameters(2, 2000, 0.9, 42);
  p.t_end = 50;
  p.contact_statistics = true;
  const RunResult a = run_dsmc(p), b = run_dsmc(p);
  const std::vector<double> grid = sample_times(p);
  BOOST_TEST_REQUIRE(a.samples.size() == grid.size());
  BOOST_TEST_REQUIRE(b.samples.size() == grid.size());
  bool identical = true;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const Sample &x = a.samples[k], &y = b.samples[k];
    identical = identical && x.t == grid[k] && y.t == grid[k] &&
                std::memcmp(&x.temperature, &y.temperature, sizeof(double)) == 0 &&
                std::memcmp(&x.a2, &y.a2, sizeof(double)) == 0 && x.collisions == y.collisions &&
                x.contacts.count == y.contacts.count &&
                std::memcmp(&x.contacts.sum_g2, &y.contacts.sum_g2, sizeof(double)) == 0;
    BOOST_TEST(x.events == x.collisions);
    BOOST_TEST(std::isnan(x.velocity_mode));
    BOOST_TEST(std::isnan(x.density_mode));
  }
  BOOST_TEST(identical);
  BOOST_TEST(a.samples.front().temperature == 1.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST((a.stop_reason == StopReason::t_end));
  BOOST_TEST(a.collisions > 0u);
  p.seed = 43;
  BOOST_TEST(run_dsmc(p).collisions != a.collisions);
}

// Cooling over forty decades (N = 500, eps = 0.5, to t = 1e23), as the MD's stress test does:
// collisions conserve momentum only up to rounding, and a drift of the centre of mass, kept while
// the gas cools, once held the kinetic energy (T froze near 8e-34 with a2 = -1/2, all particles
// at one velocity, and the acceptance bound set by the drift rejected nearly every candidate, so
// that a longer t_end hardly advanced). The drift is removed when it matters: T keeps falling as
// Haff's law, T ~ t^-2 (a factor 100 per decade of time), and a2 stays near the cooling state's.
BOOST_AUTO_TEST_CASE(cooling_over_forty_decades_keeps_the_centre_of_mass_at_rest) {
  Parameters p = gas_parameters(2, 500, 0.5, 7);
  p.t_end = 1e23;
  p.samples_per_decade = 1;
  const RunResult r = run_dsmc(p);
  BOOST_REQUIRE((r.stop_reason == StopReason::t_end));
  const Sample& last = r.samples.back();
  const Sample& decade_before = r.samples[r.samples.size() - 2];
  BOOST_TEST_MESSAGE("DSMC t = " << last.t << ": T = " << last.temperature << ", a2 = " << last.a2
                                 << " after " << r.collisions << " collisions; T a decade before "
                                 << decade_before.temperature);
  BOOST_TEST(last.temperature < 1e-40);
  BOOST_TEST(decade_before.temperature / last.temperature > 50.0);
  BOOST_TEST(std::fabs(last.a2) < 0.3);
}

// Cooling without end (t_end = 1e300): the run stops with temperature_floor when T/T0 falls
// below 1e-300, as the MD engine does, instead of printing T = 0 once the internal scale's square
// overflows.
BOOST_AUTO_TEST_CASE(cooling_stops_at_the_floor_of_double_precision) {
  Parameters p = gas_parameters(2, 500, 0.5, 9);
  p.samples_per_decade = 1;
  const RunResult r = run_dsmc(p);
  BOOST_REQUIRE(!r.samples.empty());
  BOOST_TEST_MESSAGE("DSMC: " << stop_message(r) << "; T = " << r.samples.back().temperature);
  BOOST_TEST((r.stop_reason == StopReason::temperature_floor));
  BOOST_TEST(r.samples.back().temperature < k_temperature_floor);
  BOOST_TEST(r.samples.back().temperature > 0.01 * k_temperature_floor);
  bool positive = true;
  for (const Sample& s : r.samples) positive = positive && s.temperature > 0;
  BOOST_TEST(positive);
}

BOOST_AUTO_TEST_CASE(stops_and_bad_input) {
  Parameters p = gas_parameters(2, 1000, 0.5, 3);
  p.t_end = 1e6;
  p.max_collisions = 12345;
  RunResult r = run_dsmc(p);
  BOOST_TEST((r.stop_reason == StopReason::max_collisions));
  BOOST_TEST(r.collisions == 12345u);
  p.max_collisions = 0;
  p.min_temperature = 0.3;
  r = run_dsmc(p);
  BOOST_TEST((r.stop_reason == StopReason::min_temperature));
  BOOST_TEST(r.samples.back().temperature < 0.3);
  BOOST_TEST(r.samples.back().temperature > 0.29);
  auto message_of = [](const Parameters& bad) -> std::string {
    try {
      run_dsmc(bad);
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "";
  };
  Parameters bad = gas_parameters(2, 1000, 0.9, 1);
  bad.t_end = 1;
  bad.tc = 1e-3;
  BOOST_TEST(message_of(bad).rfind("tc:", 0) == 0u);
  bad.tc = 0;
  bad.snapshot_times = {0.5};
  BOOST_TEST(message_of(bad).rfind("snapshot_times:", 0) == 0u);
  bad.snapshot_times.clear();
  bad.relax_collisions_per_particle = 20;
  BOOST_TEST(message_of(bad).rfind("relax_collisions_per_particle:", 0) == 0u);
  bad.relax_collisions_per_particle = 0;
  bad.dimension = 4;
  BOOST_TEST(message_of(bad).rfind("dimension:", 0) == 0u);
  bad.dimension = 2;
  BOOST_TEST(message_of(bad).empty());
}

// The paper's state point (d = 2, n = 0.05, N = 5000; ε = 0.8, 0.9) by DSMC, analysed exactly as
// the MD runs are (validation::analyse_run: the τ0 estimator over the window after 3 collisions per
// particle; no break-down indicator, since there are no positions). A measurement, reported: a2,
// A and the collision-averaged dyad <D> with standard errors over the runs, beside the theory at
// b = 0 (a gas without velocity correlations) evaluated at the DSMC's own a2 and at the first
// Sonine a2. The theory's f is truncated at the first Sonine term and the Haff fit sees the a2
// transient, so agreement is expected only to O(1e-3), not within these standard errors; the
// exact properties of the method are the fast tests above. Asserted: every run was analysed.
// Slow: run only by name (label slow).
BOOST_AUTO_TEST_CASE(paper_point_precision, *boost::unit_test::disabled()) {
  constexpr std::int64_t particles = 5000;
  constexpr int runs = 200;
  for (double restitution : {0.8, 0.9}) {
    std::vector<double> a_values, a2_values, dyad_values;
    std::uint64_t collisions = 0;
    const double t_end = 4.0 * molchaos::validation::theory_tau0(2, 0.05, restitution);
    double cpu = 0;
    for (int r = 0; r < runs; ++r) {
      Parameters p = gas_parameters(2, particles, restitution, 1 + r);
      p.density = 0.05;
      p.t_end = t_end;
      p.samples_per_decade = 40;
      p.contact_statistics = true;
      const double cpu0 = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
      const RunResult result = run_dsmc(p);
      cpu += static_cast<double>(std::clock()) / CLOCKS_PER_SEC - cpu0;
      collisions += result.collisions;
      const auto analysis = molchaos::validation::analyse_run(result, {});
      BOOST_TEST_REQUIRE(analysis.ok, analysis.message);
      BOOST_TEST_REQUIRE((result.stop_reason == StopReason::t_end));
      a_values.push_back(analysis.A);
      a2_values.push_back(analysis.a2);
      dyad_values.push_back(analysis.mean_dyad);
    }
    const MeanError a = mean_error(a_values), a2 = mean_error(a2_values),
                    dyad = mean_error(dyad_values);
    molchaos::theory::CoolingInputs in;
    in.dimension = 2;
    in.density = 0.05;
    in.restitution = restitution;
    const auto sonine = molchaos::theory::predict_cooling(in);
    in.a2 = a2.mean;
    const auto at_a2 = molchaos::theory::predict_cooling(in);
    in.a2 = a2.mean + a2.error;
    const double a_slope_error = std::fabs(molchaos::theory::predict_cooling(in).A.value -
                                           at_a2.A.value);  // A's change over one SE of a2
    const auto integrals = molchaos::theory::contact_integrals(2, a2.mean, 3.0);
    const auto dyad_theory = integrals.mean_dyad(0.0);
    const double dyad_slope_error = std::fabs(
        molchaos::theory::contact_integrals(2, a2.mean + a2.error, 3.0).mean_dyad(0.0).value -
        dyad_theory.value);
    const double a_dev =
        (a.mean - at_a2.A.value) / std::sqrt(a.error * a.error + at_a2.A.error * at_a2.A.error +
                                             a_slope_error * a_slope_error);
    const double dyad_dev =
        (dyad.mean - dyad_theory.value) /
        std::sqrt(dyad.error * dyad.error + dyad_theory.error * dyad_theory.error +
                  dyad_slope_error * dyad_slope_error);
    BOOST_TEST_MESSAGE("DSMC d = 2, n = 0.05, N = "
                       << particles << ", eps = " << restitution << ", " << runs << " runs, "
                       << collisions << " collisions, " << cpu
                       << " CPU s in run_dsmc: a2 = " << a2.mean << " +- " << a2.error
                       << " (first Sonine " << sonine.a2 << "); A = " << a.mean << " +- " << a.error
                       << " (theory b = 0 at the DSMC a2: " << at_a2.A.value << ", " << a_dev
                       << " SE; at first Sonine a2: " << sonine.A_uncorrelated.value
                       << "); <D> = " << dyad.mean << " +- " << dyad.error
                       << " (theory b = 0: " << dyad_theory.value << ", " << dyad_dev << " SE)");
  }
}

// The realisation does not depend on where the run is sampled: a run sampled on a finer grid,
// or from a later first sample, passes through the same states at the times both sample
// (a candidate whose time passes a sample time waits for the next advance instead of being
// dropped, which gave another gas for every grid).
BOOST_AUTO_TEST_CASE(sampling_times_do_not_change_the_gas) {
  for (int d : {2, 3}) {
    Parameters coarse = gas_parameters(d, 2000, 0.9, 7);
    coarse.t_end = 300;
    coarse.samples_per_decade = 10;
    Parameters fine = coarse;
    fine.samples_per_decade = 40;
    Parameters shifted = coarse;
    shifted.t_first_sample = 0.0123;
    const RunResult a = run_dsmc(coarse), b = run_dsmc(fine), c = run_dsmc(shifted);
    std::size_t common = 0;
    for (const Sample& s : a.samples)
      for (const Sample& r : b.samples)
        if (r.t == s.t) {
          ++common;
          BOOST_TEST(r.temperature == s.temperature);
          BOOST_TEST(r.collisions == s.collisions);
        }
    BOOST_TEST(common >= 20u);                 // every decade's coarse times, t_end among them
    for (const RunResult* other : {&b, &c}) {  // at t_end
      BOOST_TEST(other->samples.back().t == a.samples.back().t);
      BOOST_TEST(other->samples.back().temperature == a.samples.back().temperature);
      BOOST_TEST(other->collisions == a.collisions);
    }
  }
}

// The MD engine's limits (4 cells a side, the densest initial configuration for N) are not
// DSMC's, which keeps velocities only: it is bounded by close packing alone.
BOOST_AUTO_TEST_CASE(densities_beyond_the_md_start_are_dsmcs) {
  Parameters p = gas_parameters(3, 512, 0.9, 1);
  p.density = 1.0;  // beyond N = 512's simple cubic start (0.999999), below close packing
  p.t_end = 1;
  p.method = Method::edmd;
  BOOST_CHECK_THROW(validate(p), std::invalid_argument);
  p.method = Method::dsmc;
  BOOST_CHECK_NO_THROW(validate(p));
  p.density = 1.5;  // above close packing (sqrt 2)
  BOOST_CHECK_THROW(validate(p), std::invalid_argument);
}
