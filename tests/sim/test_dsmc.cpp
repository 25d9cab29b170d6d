// The DSMC method against exact results: the contact-vector law, the elastic gas's stationary
// (microcanonical Maxwell) state, Enskog's collision frequency, the molecular-chaos moments of the
// colliding pairs, the initial cooling rate μ2(a2 = 0); the long-time a2 against the first Sonine
// approximation (reported). Reproducibility, stops and bad input: test_dsmc_runs.cpp. Statistical
// claims are tested as a whole (Hotelling's T² over all quantities, or χ²) with a false-alarm
// probability of 1e-3.
#define BOOST_TEST_MODULE sim_dsmc
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_sf_gamma.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "dsmc_test_support.hpp"
#include "molchaos/sim/dsmc.hpp"
#include "molchaos/sim/dsmc_contact.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/sonine.hpp"

using namespace molchaos::sim;
using molchaos::sim::testing::gas_parameters;
using molchaos::sim::testing::mean_error;
using molchaos::sim::testing::MeanError;

namespace {

constexpr double k_false_alarm = 1e-3;

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
// Ernst; the paper's Eq. (25) for d = 2). Not asserted equal (the first Sonine approximation is
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
