// Linear hydrodynamics of the HCS: the Enskog coefficients against the published elastic closed
// forms, the cooling rate against Haff's law of cooling.hpp, L_c → ∞ as ε → 1, and the sign
// changes of the mode growth rates at k⊥ and k∥.
#define BOOST_TEST_MODULE theory_hydrodynamics
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/hydrodynamics.hpp"

using namespace molchaos::theory;

namespace {
TransportCoefficients at(int d, double n, double eps) {
  return transport_coefficients({d, n, eps, std::nullopt});
}
}  // namespace

// Elastic limit: η* and κ* equal Enskog's first approximation (Gass 1971 for disks: 1/χ + 2φ +
// (1 + 8/π)φ²χ and 1/χ + 3φ + (9/4 + 4/π)φ²χ; Chapman–Cowling for spheres), μ* = ζ* = 0, and
// the pressure and compressibility those of the equation of state behind g2 (Henderson:
// p* = (1 + φ²/8)/(1 − φ)²; Carnahan–Starling). Exact algebra: rounding only (1e-13).
BOOST_AUTO_TEST_CASE(elastic_limit_is_enskog) {
  for (int d : {2, 3})
    for (double n : {1e-4, 0.05, 0.1, 0.3, 0.6}) {
      const auto c = at(d, n, 1.0);
      const double phi = c.packing_fraction, chi = c.g2;
      BOOST_TEST(std::abs(c.shear_viscosity / enskog_elastic_shear_viscosity(d, phi, chi) - 1) <=
                 1e-13);
      BOOST_TEST(
          std::abs(c.thermal_conductivity / enskog_elastic_thermal_conductivity(d, phi, chi) - 1) <=
          1e-13);
      BOOST_TEST(c.cooling_rate == 0.0);
      BOOST_TEST(c.heat_flux_density == 0.0);
      const double p_eos = d == 2 ? (1 + phi * phi / 8) / ((1 - phi) * (1 - phi))
                                  : (1 + phi + phi * phi - phi * phi * phi) / std::pow(1 - phi, 3);
      BOOST_TEST(std::abs(c.pressure / p_eos - 1) <= 1e-13);
      // C = ∂(n p*)/∂n by a central difference of the equation of state (error ~ h² ≈ 1e-10).
      const double h = 1e-5 * phi;
      auto np = [&](double f) {
        return f * (d == 2 ? (1 + f * f / 8) / ((1 - f) * (1 - f))
                           : (1 + f + f * f - f * f * f) / std::pow(1 - f, 3));
      };
      BOOST_TEST(std::abs(c.compressibility / ((np(phi + h) - np(phi - h)) / (2 * h)) - 1) <= 1e-8);
      BOOST_TEST(std::isinf(critical_box_size(c)));
    }
}

// ζ* ν0 is the Haff rate 2/τ0 of cooling.hpp (with the same a2 entering μ2 at first order:
// μ2/μ2(0,0) = 1 + 3a2/16 + O(a2²) by the coefficient table; compared at the 1e-3 level that
// the dropped a2² term, 9/1024 a2² < 1e-5, and quadrature leave far below).
BOOST_AUTO_TEST_CASE(cooling_rate_matches_haff) {
  for (int d : {2, 3})
    for (double eps : {0.5, 0.8, 0.93}) {
      const double n = 0.05;
      const auto c = at(d, n, eps);
      CoolingInputs in;
      in.dimension = d;
      in.density = n;
      in.restitution = eps;
      const auto p = predict_cooling(in);
      const double rate_per_collision = c.cooling_rate * c.collision_ratio;
      const double haff = 2.0 / p.tau0.value / p.enskog_collision_frequency;
      BOOST_TEST(std::abs(rate_per_collision / haff - 1) <= 1e-3);
    }
}

BOOST_AUTO_TEST_CASE(critical_box_diverges_in_the_elastic_limit) {
  for (int d : {2, 3}) {
    double previous = 0;
    for (double eps : {0.5, 0.8, 0.9, 0.95, 0.99, 0.999, 0.9999}) {
      const double L = critical_box_size(at(d, 0.05, eps));
      BOOST_TEST(L > previous);
      previous = L;
    }
    // k⊥*² = ζ*/(2η*) ∝ (1 − ε²) near ε = 1, so L_c √(1 − ε²) tends to 2πℓ √(2η*/ζ̂) with
    // ζ̂ = (d+2)/(4d) χ; the relative gap closes ∝ (1 − ε).
    const auto el = at(d, 0.05, 1.0);
    const double limit = 2 * M_PI * el.length_unit *
                         std::sqrt(2 * el.shear_viscosity / ((d + 2.0) / (4.0 * d) * el.g2));
    double gap_prev = 1;
    for (double one_minus : {1e-2, 1e-3, 1e-4}) {
      const double eps = 1 - one_minus;
      const double gap =
          std::abs(critical_box_size(at(d, 0.05, eps)) * std::sqrt(1 - eps * eps) / limit - 1);
      BOOST_TEST(gap < gap_prev);
      BOOST_TEST(gap <= 10 * one_minus);
      gap_prev = gap;
    }
  }
}

BOOST_AUTO_TEST_CASE(growth_rates_change_sign_at_the_critical_wavenumbers) {
  for (int d : {2, 3})
    for (double n : {0.05, 0.1, 0.3})
      for (double eps : {0.7, 0.9, 0.93}) {
        const auto c = at(d, n, eps);
        const double ks = critical_shear_wavenumber(c), kh = critical_heat_wavenumber(c);
        BOOST_TEST(std::abs(shear_mode_rate(c, ks)) <= 1e-14);
        BOOST_TEST(shear_mode_rate(c, 0.99 * ks) > 0);
        BOOST_TEST(shear_mode_rate(c, 1.01 * ks) < 0);
        BOOST_TEST_REQUIRE(kh > 0);
        BOOST_TEST(longitudinal_mode_rate(c, 0.99 * kh) > 0);
        BOOST_TEST(longitudinal_mode_rate(c, 1.01 * kh) < 0);
        BOOST_TEST(kh < ks);  // the shear mode goes unstable first as the box grows
      }
}

// S⊥(k, τ): 1 at τ = 0, stationary νk²/(νk² − ζ/2) above k⊥, the closed-form inverse.
BOOST_AUTO_TEST_CASE(transverse_structure_factor_limits) {
  const auto c = at(2, 0.05, 0.93);
  const double ks = critical_shear_wavenumber(c);
  for (double k : {0.5 * ks, 2.0 * ks}) BOOST_TEST(transverse_structure_factor(c, k, 0) == 1.0);
  const double k = 2.0 * ks;  // stationary value 4/(4 − 1) = 4/3
  BOOST_TEST(std::abs(transverse_structure_factor(c, k, 1e4) - 4.0 / 3.0) <= 1e-12);
  BOOST_TEST(std::abs(stationary_transverse_structure_factor(c, k) - 4.0 / 3.0) <= 1e-12);
  BOOST_TEST(std::isinf(stationary_transverse_structure_factor(c, 0.5 * ks)));  // it grows
  BOOST_TEST(std::isinf(collisions_to_reach(c, k, 1.5)));
  const double tau = collisions_to_reach(c, 0.5 * ks, 10.0);
  BOOST_TEST(std::abs(transverse_structure_factor(c, 0.5 * ks, tau) / 10.0 - 1) <= 1e-12);
}

// The dilute heat-flux coefficients in the first Sonine approximation (Brey et al. 1998): with
// f0 = f_M(1 + a2 S2), x = mV²/2T and S = x − (d+2)/2, the temperature-gradient source projects
// onto S(V)V as ⟨xS²⟩(1 + 2a2) and the density-gradient source as a2⟨xSS2⟩, moments of the
// Gamma(d/2) distribution of x. So (ν_κ* − 2ζ*)κ* = ((d−1)/d)(1 + 2a2) and
// (2ν_κ* − 3ζ*)μ* = 2ζ*κ* + 2((d−1)/d) a2⟨xSS2⟩/⟨xS²⟩; ν_κ* is eliminated between the two. At
// n = 1e-9 the collisional parts are below the tolerance.
BOOST_AUTO_TEST_CASE(dilute_heat_flux_coefficients_follow_the_sonine_projections) {
  for (int d : {2, 3})
    for (double eps : {0.3, 0.6, 0.8, 0.93}) {
      const auto c = at(d, 1e-9, eps);
      const double h = d / 2.0;
      auto moment = [h](int k) { return std::tgamma(h + k) / std::tgamma(h); };  // ⟨x^k⟩
      // S = x − (h+1), S2 = x²/2 − (h+1)x + h(h+1)/2: ⟨xS²⟩ and ⟨xSS2⟩ by their moments.
      const double xs2 = moment(3) - 2 * (h + 1) * moment(2) + (h + 1) * (h + 1) * moment(1);
      const double xss2 = 0.5 * moment(4) - 1.5 * (h + 1) * moment(3) +
                          ((h + 1) * (h + 1) + 0.5 * h * (h + 1)) * moment(2) -
                          0.5 * h * (h + 1) * (h + 1) * moment(1);
      const double source = (d - 1.0) / d;
      const double zeta = c.cooling_rate, kappa = c.thermal_conductivity, a2 = c.a2;
      const double nu_kappa = 2 * zeta + source * (1 + 2 * a2) / kappa;
      const double mu =
          (2 * zeta * kappa + 2 * source * a2 * xss2 / xs2) / (2 * nu_kappa - 3 * zeta);
      BOOST_TEST_INFO("d = " << d << ", eps = " << eps << ", a2 = " << a2);
      BOOST_TEST(c.heat_flux_density == mu, boost::test_tools::tolerance(1e-6));
    }
}

// The dense hard-sphere gas: Garzó and Dufty's (1999) d = 3 expressions, written out here in their
// own variables (c* = 2a2, the HCS coefficient of their eq. for c*; p* = 1 + 2(1+α)φχ; χ' =
// dχ/dφ), against the code's d-dimensional form: μ* = μ_k*(1 + (6/5)φχ(1+α)) with
// μ_k* = 2[ζ*κ_k*(1 + φχ'/χ) + (p*/3 + (2/3)φ(1+α)(χ + φχ'))c*
//          − (4/5)φχ(1 + φχ'/(2χ))(1+α)(α(1−α) + (4/3 + α(1−α))c*/4)]/(2ν_κ* − 3ζ*),
// κ_k* = (2/3)[1 + (1+p*)c*/2 + (3/5)φχ(1+α)²(2α − 1 + ((1+α)/2 − 5/(3(1+α)))c*)]/(ν_κ* − 2ζ*),
// ν_κ* = (χ/3)(1+α)[1 + (33/16)(1−α) + (19 − 3α)c*/1024], ζ* = (5/12)χ(1−α²)(1 + 3c*/32).
BOOST_AUTO_TEST_CASE(dense_heat_flux_coefficient_is_garzo_dufty_in_three_dimensions) {
  for (double n : {0.05, 0.2, 0.6})
    for (double alpha : {0.5, 0.7, 0.9, 0.99}) {
      const auto c = at(3, n, alpha);
      const double phi = std::numbers::pi / 6.0 * n;
      const double chi = (1 - phi / 2) / std::pow(1 - phi, 3);
      const double chi_prime = (2.5 - phi) / std::pow(1 - phi, 4);  // d/dφ of Carnahan–Starling
      const double cs = 32 * (1 - alpha) * (1 - 2 * alpha * alpha) /
                        (81 - 17 * alpha + 30 * alpha * alpha * (1 - alpha));
      const double p = 1 + 2 * (1 + alpha) * phi * chi;
      const double zeta = 5.0 / 12.0 * chi * (1 - alpha * alpha) * (1 + 3 * cs / 32);
      const double nu =
          chi / 3 * (1 + alpha) * (1 + 33.0 / 16.0 * (1 - alpha) + (19 - 3 * alpha) * cs / 1024);
      const double kappa_k =
          2.0 / 3.0 *
          (1 + (1 + p) * cs / 2 +
           0.6 * phi * chi * (1 + alpha) * (1 + alpha) *
               (2 * alpha - 1 + ((1 + alpha) / 2 - 5 / (3 * (1 + alpha))) * cs)) /
          (nu - 2 * zeta);
      const double mu_k = 2 *
                          (zeta * kappa_k * (1 + phi * chi_prime / chi) +
                           (p / 3 + 2.0 / 3.0 * phi * (1 + alpha) * (chi + phi * chi_prime)) * cs -
                           0.8 * phi * chi * (1 + phi * chi_prime / (2 * chi)) * (1 + alpha) *
                               (alpha * (1 - alpha) + (4.0 / 3.0 + alpha * (1 - alpha)) * cs / 4)) /
                          (2 * nu - 3 * zeta);
      BOOST_TEST_INFO("n = " << n << ", alpha = " << alpha);
      BOOST_TEST(c.a2 == cs / 2, boost::test_tools::tolerance(1e-13));
      BOOST_TEST(c.heat_flux_density == mu_k * (1 + 1.2 * phi * chi * (1 + alpha)),
                 boost::test_tools::tolerance(1e-12));
    }
}

// The dense disk gas: μ* from the Chapman–Enskog projection onto S(V)V done for d = 2 alone
// (the first-gradient Enskog operator with χ at the contact midpoint, f0 = f_M(1 + a2 S2)),
// its terms collected in the disks' own variables. The ∇n source is a2/2 (kinetic) plus
// (1+α)φχ(2 + φχ'/χ)[3α(α−1)/16 + a2(3α² − 3α + 14)/32] (collisional, C's collisional part
// included), with φ = πn/4, Henderson's χ = (1 − 7φ/16)/(1 − φ)², χ' = (25/16 − 7φ/16)/(1 − φ)³;
// μ_k* = 2[ζ*(1 + φχ'/χ)κ_k* + source]/(2ν_κ* − 3ζ*), μ* = μ_k*(1 + (3/4)φχ(1+α)), with
// ζ* = ½χ(1−α²)(1 + 3a2/16), ν_κ* = ½(1+α)χ[½ + 15(1−α)/8 + (14 − 6α)a2/512],
// κ_k* = ½[1 + 2a2 + (3/8)φχ(1+α)²(2α − 1 + a2(1+α))]/(ν_κ* − 2ζ*),
// a2 = 16(1−α)(1−2α²)/(57 − 25α + 30α²(1−α)). At n = 0.5, α = 0.9: μ* = 0.4543832.
BOOST_AUTO_TEST_CASE(dense_heat_flux_coefficient_of_disks_is_the_two_dimensional_projection) {
  for (double n : {0.05, 0.2, 0.5, 0.7})
    for (double alpha : {0.5, 0.8, 0.9, 0.99}) {
      const auto c = at(2, n, alpha);
      const double phi = std::numbers::pi / 4.0 * n;
      const double chi = (1 - 7 * phi / 16) / std::pow(1 - phi, 2);
      const double dl = phi * (25.0 / 16.0 - 7 * phi / 16) / std::pow(1 - phi, 3) / chi;
      const double a2 = 16 * (1 - alpha) * (1 - 2 * alpha * alpha) /
                        (57 - 25 * alpha + 30 * alpha * alpha * (1 - alpha));
      const double zeta = 0.5 * chi * (1 - alpha * alpha) * (1 + 3 * a2 / 16);
      const double nu =
          0.5 * (1 + alpha) * chi * (0.5 + 15 * (1 - alpha) / 8 + (14 - 6 * alpha) * a2 / 512);
      const double kappa_k =
          0.5 *
          (1 + 2 * a2 +
           0.375 * phi * chi * (1 + alpha) * (1 + alpha) * (2 * alpha - 1 + a2 * (1 + alpha))) /
          (nu - 2 * zeta);
      const double source = a2 / 2 + (1 + alpha) * phi * chi * (2 + dl) *
                                         (3 * alpha * (alpha - 1) / 16 +
                                          a2 * (3 * alpha * alpha - 3 * alpha + 14) / 32);
      const double mu_k = 2 * (zeta * (1 + dl) * kappa_k + source) / (2 * nu - 3 * zeta);
      BOOST_TEST_INFO("n = " << n << ", alpha = " << alpha);
      BOOST_TEST(c.a2 == a2, boost::test_tools::tolerance(1e-13));
      BOOST_TEST(c.heat_flux_density == mu_k * (1 + 0.75 * phi * chi * (1 + alpha)),
                 boost::test_tools::tolerance(1e-12));
      if (n == 0.5 && alpha == 0.9)
        BOOST_TEST(c.heat_flux_density == 0.4543832, boost::test_tools::tolerance(1e-7));
    }
}

// At strong dissipation μ* outgrows κ* (Cκ* − p*μ* < 0 with ζ*(p*g − C/2) > 0): the determinant
// of the longitudinal matrix never vanishes and its largest eigenvalue stays positive at every
// k, so no k∥ exists (critical_heat_wavenumber gave 0, printed as 2π/k∥ = inf, read as never
// unstable). The flag is checked against the eigenvalues themselves over eight decades of k, at
// restitutions either side of where it turns on (ε ≈ 0.35 for disks, 0.19 for spheres at
// n = 0.05); where it is off, k∥ exists and the rate changes sign there.
BOOST_AUTO_TEST_CASE(heat_mode_unstable_at_every_wavelength_at_strong_dissipation) {
  BOOST_TEST(heat_mode_unstable_at_every_wavelength(at(2, 0.05, 0.2)));
  BOOST_TEST(heat_mode_unstable_at_every_wavelength(at(3, 0.05, 0.1)));
  for (int d : {2, 3})
    for (double eps : {0.05, 0.1, 0.2, 0.3, 0.4, 0.6, 0.9}) {
      const auto c = at(d, 0.05, eps);
      BOOST_TEST_INFO("d = " << d << ", eps = " << eps);
      if (heat_mode_unstable_at_every_wavelength(c)) {
        for (double ks = 1e-4; ks <= 1e4; ks *= std::sqrt(10.0))
          BOOST_TEST(longitudinal_mode_rate(c, ks / c.length_unit) > 0);
        BOOST_TEST(critical_heat_wavenumber(c) == 0.0);
      } else {
        const double kh = critical_heat_wavenumber(c);
        BOOST_TEST(kh > 0.0);
        BOOST_TEST(longitudinal_mode_rate(c, 0.99 * kh) > 0);
        BOOST_TEST(longitudinal_mode_rate(c, 1.01 * kh) < 0);
      }
    }
  for (int d : {2, 3}) BOOST_TEST(!heat_mode_unstable_at_every_wavelength(at(d, 0.05, 1.0)));
}
