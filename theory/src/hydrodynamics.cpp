// Enskog transport coefficients of the HCS and its linear hydrodynamic modes (see the header for
// sources and units; the linearised equations are derived in the comments below).
#include "molchaos/theory/hydrodynamics.hpp"

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/dimension.hpp"
#include "molchaos/theory/sonine.hpp"

namespace molchaos::theory {
namespace {

constexpr double k_pi = std::numbers::pi;

/// η0 at T = 1: (d+2)/8 Γ(d/2) π^{−(d−1)/2}: 1/(2√π) for disks, 5/(16√π) for spheres.
double dilute_viscosity_unit(int d) {
  return (d + 2) / 8.0 * std::tgamma(0.5 * d) * std::pow(k_pi, -0.5 * (d - 1));
}

/// φ ∂ln χ/∂φ of the contact values of contact_value.hpp (Henderson, Carnahan–Starling).
double log_derivative_g2(int d, double phi) {
  if (d == 2) return phi * (2.0 / (1.0 - phi) - (7.0 / 16.0) / (1.0 - 7.0 * phi / 16.0));
  return phi * (3.0 / (1.0 - phi) - 0.5 / (1.0 - 0.5 * phi));
}

/// ω_E/ν0 with ω_E = 2nσχ√(πT) (d = 2), 4nσ²χ√(πT) (d = 3) (cooling.hpp) and ν0 = nT/η0.
double enskog_frequency_over_nu0(int d, double g2) {
  const double surface = d == 2 ? 2.0 : 4.0;
  return surface * g2 * std::sqrt(k_pi) * dilute_viscosity_unit(d);
}

/// The kinetic parts and collision frequencies of Garzó & Dufty (1999), written for d dimensions
/// as in Garzó (2005): first Sonine approximation with the HCS a2 (a2 = c/2 of Garzó–Dufty).
struct KineticParts {
  double nu_eta, nu_kappa, eta_k, kappa_k, mu_k;
};

KineticParts kinetic_parts(int d, double alpha, double phi, double chi, double a2, double zeta,
                           double compressibility) {
  KineticParts k{};
  // ν_η* = (3/(4d)) χ (1 − α + 2d/3)(1 + α)(1 − a2/32); elastic dilute value 1.
  k.nu_eta =
      3.0 / (4.0 * d) * chi * (1.0 - alpha + 2.0 * d / 3.0) * (1.0 + alpha) * (1.0 - a2 / 32.0);
  // ν_κ* = ((1+α)/d) χ [(d−1)/2 + (3/16)(d+8)(1−α) + (4 + 5d − 3(4−d)α) a2/512];
  // elastic dilute value (d−1)/d, so that κ* → 1.
  k.nu_kappa = (1.0 + alpha) / d * chi *
               ((d - 1) / 2.0 + 3.0 / 16.0 * (d + 8) * (1.0 - alpha) +
                (4.0 + 5.0 * d - 3.0 * (4 - d) * alpha) * a2 / 512.0);
  const double two_d2 = std::pow(2.0, d - 2);
  // η_k* = [1 − 2^{d−2}/(d+2) (1+α)(1−3α) φχ]/(ν_η* − ζ*/2)  (Garzó–Dufty eq. for η_k*).
  k.eta_k = (1.0 - two_d2 / (d + 2) * (1.0 + alpha) * (1.0 - 3.0 * alpha) * phi * chi) /
            (k.nu_eta - 0.5 * zeta);
  // κ_k* = ((d−1)/d)[1 + 2a2 + 3·2^{d−3}/(d+2) φχ(1+α)²(2α − 1 + a2(1+α))]/(ν_κ* − 2ζ*).
  k.kappa_k = (d - 1.0) / d *
              (1.0 + 2.0 * a2 +
               3.0 * std::pow(2.0, d - 3) / (d + 2) * phi * chi * (1.0 + alpha) * (1.0 + alpha) *
                   (2.0 * alpha - 1.0 + a2 * (1.0 + alpha))) /
              (k.nu_kappa - 2.0 * zeta);
  // μ_k* = 2[ζ*(1 + φ∂_φ ln χ) κ_k* + C (d−1) a2/d − C_d φχ(1 + ½φ∂_φ ln χ)(1+α)
  //          (α(1−α) + (B_d + α(1−α)) a2/2)]/(2ν_κ* − 3ζ*)
  // with C_d = 3·2^{d−2}(d−1)/(d(d+2)), B_d = 2(d−1)/3 and C = p*(1 + φ∂_φ ln p*) the
  // compressibility of transport_coefficients(). Dilute, it is Brey et al.'s form: the
  // density-gradient source's projection on S(V)V is a2 where the temperature gradient's is
  // 1 + 2a2 (κ_k* above), both over (d−1)/d, and ζ*(1 + φ∂_φ ln χ) is the density derivative of
  // the Enskog cooling rate (ζ ∝ nχ). At finite density the pressure's density derivative C and
  // the collisional transfer of the first-order distribution (the last term) enter: Garzó and
  // Dufty (1999), whose d = 3 form (C_3 = 4/5, B_3 = 4/3) the tests check term by term; the d
  // dependence of C_d and B_d is that of the same first-Sonine projection in d dimensions.
  const double dlog = log_derivative_g2(d, phi);
  const double c_d = 3.0 * two_d2 * (d - 1) / (d * (d + 2.0));
  const double b_d = 2.0 * (d - 1) / 3.0;
  const double transfer = c_d * phi * chi * (1.0 + 0.5 * dlog) * (1.0 + alpha) *
                          (alpha * (1.0 - alpha) + (b_d + alpha * (1.0 - alpha)) * a2 / 2.0);
  k.mu_k = zeta > 0 ? 2.0 *
                          (zeta * (1.0 + dlog) * k.kappa_k + compressibility * (d - 1.0) * a2 / d -
                           transfer) /
                          (2.0 * k.nu_kappa - 3.0 * zeta)
                    : 0.0;
  return k;
}

}  // namespace

double enskog_elastic_shear_viscosity(int dimension, double phi, double g2) {
  require_dimension(dimension);
  if (dimension == 2) return 1.0 / g2 + 2.0 * phi + (1.0 + 8.0 / k_pi) * phi * phi * g2;
  const double b = 4.0 * phi;  // Enskog's b n = 2πnσ³/3
  return 1.0 / g2 + 0.8 * b + 4.0 / 25.0 * (1.0 + 12.0 / k_pi) * b * b * g2;
}

double enskog_elastic_thermal_conductivity(int dimension, double phi, double g2) {
  require_dimension(dimension);
  if (dimension == 2) return 1.0 / g2 + 3.0 * phi + (9.0 / 4.0 + 4.0 / k_pi) * phi * phi * g2;
  const double b = 4.0 * phi;
  return 1.0 / g2 + 1.2 * b + 9.0 / 25.0 * (1.0 + 32.0 / (9.0 * k_pi)) * b * b * g2;
}

TransportCoefficients transport_coefficients(const HydrodynamicInputs& in) {
  require_dimension(in.dimension);
  require_density(in.dimension, in.density);
  require_restitution(in.restitution);
  const int d = in.dimension;
  const double alpha = in.restitution;
  TransportCoefficients c;
  c.dimension = d;
  c.packing_fraction = packing_fraction(d, in.density);
  c.g2 = contact_value_g2(d, c.packing_fraction);
  c.a2 = in.a2 ? *in.a2 : a2_first_sonine(d, alpha);
  const double phi = c.packing_fraction, chi = c.g2, a2 = c.a2;
  // ζ* = (d+2)/(4d) χ (1 − α²)(1 + 3a2/16): the suite's Haff rate 2/τ0 (cooling.hpp) over ν0.
  c.cooling_rate = (d + 2.0) / (4.0 * d) * chi * (1.0 - alpha * alpha) * (1.0 + 3.0 * a2 / 16.0);
  // p* = 1 + 2^{d−2}(1+α)φχ (Garzó–Dufty); C = ∂(n p*)/∂n = 1 + 2^{d−2}(1+α)φχ(2 + φ∂lnχ).
  const double two_d2 = std::pow(2.0, d - 2);
  c.pressure = 1.0 + two_d2 * (1.0 + alpha) * phi * chi;
  c.compressibility = 1.0 + two_d2 * (1.0 + alpha) * phi * chi * (2.0 + log_derivative_g2(d, phi));
  const KineticParts k = kinetic_parts(d, alpha, phi, chi, a2, c.cooling_rate, c.compressibility);
  // γ* = 2^{2d+1}/(π(d+2)) φ²χ(1+α)(1 − a2/16);
  // η* = η_k*[1 + 2^{d−1}/(d+2) φχ(1+α)] + d/(d+2) γ*;
  // κ* = κ_k*[1 + 3·2^{d−2}/(d+2) φχ(1+α)] + 2^{2d+1}(d−1)/((d+2)²π) φ²χ(1+α)(1 + 7a2/16);
  // μ* = μ_k*[1 + 3·2^{d−2}/(d+2) φχ(1+α)]  (collisional transfer of the heat flux).
  const double four_d = std::pow(2.0, 2 * d + 1);
  c.bulk_viscosity =
      four_d / (k_pi * (d + 2)) * phi * phi * chi * (1.0 + alpha) * (1.0 - a2 / 16.0);
  c.shear_viscosity = k.eta_k * (1.0 + 2.0 * two_d2 / (d + 2) * phi * chi * (1.0 + alpha)) +
                      d / (d + 2.0) * c.bulk_viscosity;
  const double heat_transfer = 1.0 + 3.0 * two_d2 / (d + 2) * phi * chi * (1.0 + alpha);
  c.thermal_conductivity =
      k.kappa_k * heat_transfer + four_d * (d - 1) / ((d + 2.0) * (d + 2.0) * k_pi) * phi * phi *
                                      chi * (1.0 + alpha) * (1.0 + 7.0 * a2 / 16.0);
  c.heat_flux_density = k.mu_k * heat_transfer;
  c.length_unit = dilute_viscosity_unit(d) / in.density;
  c.collision_ratio = 1.0 / enskog_frequency_over_nu0(d, chi);
  return c;
}

// Transverse velocity u⊥ obeys n ∂t u⊥ = −η k² u⊥ (linearised Navier–Stokes; no pressure, no
// cooling term), while the thermal velocity √T falls as dT/dt = −ζT. The ratio w = u⊥/√T thus
// obeys dw/dt = (ζ/2 − ηk²/n) w, i.e. dw/ds = (ζ*/2 − η*(kℓ)²) w with ηk²/(nν0) = η*(kℓ)².
double shear_mode_rate(const TransportCoefficients& c, double k) {
  const double ks = k * c.length_unit;
  return (0.5 * c.cooling_rate - c.shear_viscosity * ks * ks) * c.collision_ratio;
}

// Longitudinal fields ρ1 = δn/n, w = u∥/√T, θ = δT/T, all ∝ e^{ikx}, with the Navier–Stokes
// pressure p = nTp*, heat flux q = −κ∇T − μ∇n and local cooling rate ζ ∝ nχ(n)√T:
//   dρ1/ds = −ik* w
//   dw/ds  = −ik*(C ρ1 + p* θ) + (ζ*/2 − ν_l k*²) w,      ν_l = 2(d−1)/d η* + γ*
//   dθ/ds  = −(2/d) p* ik* w − β(κ* θ + μ* ρ1) k*² − ζ*(g ρ1 + θ/2),
// with β = (d+2)/(d−1) and g = 1 + φ∂lnχ/∂φ: the energy balance (d/2) n ∂t T = −(d/2) nζT
// linearised is (d/2)(n ∂t δT + δn ∂t T) = −(d/2) δ(nζT), and δ(nζT) − δn ζT = nζT[(1 + φ∂lnχ)ρ1
// + (3/2)θ] for ζ ∝ nχ√T; θ = δT/T adds +ζθ. Substituting w = −i w̃ makes the
// matrix real. Its determinant is −k*²[ζ*(C/2 − p* g) + β k*²(Cκ* − p*μ*)], zero at k∥ below.
// Garzó (2005) adds the first-order cooling rate ζ_U ∇·u of the Enskog gas, O(φ(1−α²)); it is
// left out (it shifts the sound modes, not the zero of the determinant).
double longitudinal_mode_rate(const TransportCoefficients& c, double k) {
  const int d = c.dimension;
  const double ks = k * c.length_unit, zeta = c.cooling_rate;
  const double beta = (d + 2.0) / (d - 1.0);
  const double g = 1.0 + log_derivative_g2(d, c.packing_fraction);
  const double nu_l = 2.0 * (d - 1) / d * c.shear_viscosity + c.bulk_viscosity;
  const std::array<double, 9> m{0.0,
                                -ks,
                                0.0,
                                ks * c.compressibility,
                                0.5 * zeta - nu_l * ks * ks,
                                ks * c.pressure,
                                -(zeta * g + beta * c.heat_flux_density * ks * ks),
                                -2.0 / d * c.pressure * ks,
                                -(0.5 * zeta + beta * c.thermal_conductivity * ks * ks)};
  gsl_matrix* a = gsl_matrix_alloc(3, 3);
  for (int i = 0; i < 9; ++i) gsl_matrix_set(a, i / 3, i % 3, m[i]);
  gsl_vector_complex* eval = gsl_vector_complex_alloc(3);
  gsl_eigen_nonsymm_workspace* w = gsl_eigen_nonsymm_alloc(3);
  const int status = gsl_eigen_nonsymm(a, eval, w);
  double largest = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    largest = std::max(largest, GSL_REAL(gsl_vector_complex_get(eval, i)));
  gsl_eigen_nonsymm_free(w);
  gsl_vector_complex_free(eval);
  gsl_matrix_free(a);
  if (status != 0) throw std::runtime_error("longitudinal_mode_rate: eigenvalues did not converge");
  return largest * c.collision_ratio;
}

double critical_shear_wavenumber(const TransportCoefficients& c) {
  // ζ*/2 = η* k⊥*²  (Brey et al. 1998; Garzó 2005 with the Enskog η*).
  return std::sqrt(0.5 * c.cooling_rate / c.shear_viscosity) / c.length_unit;
}

double critical_heat_wavenumber(const TransportCoefficients& c) {
  const int d = c.dimension;
  const double beta = (d + 2.0) / (d - 1.0);
  const double g = 1.0 + log_derivative_g2(d, c.packing_fraction);
  const double k2 =
      c.cooling_rate * (c.pressure * g - 0.5 * c.compressibility) /
      (beta * (c.compressibility * c.thermal_conductivity - c.pressure * c.heat_flux_density));
  return k2 > 0 ? std::sqrt(k2) / c.length_unit : 0.0;
}

bool heat_mode_unstable_at_every_wavelength(const TransportCoefficients& c) {
  // det = −k*²[ζ*(C/2 − p* g) + β k*²(Cκ* − p*μ*)] (longitudinal_mode_rate). With
  // ζ*(p* g − C/2) > 0 and Cκ* − p*μ* ≤ 0 the bracket is negative for every k: the determinant
  // never vanishes, no eigenvalue crosses zero, and the one that is positive as k → 0 (ζ*/2,
  // the longitudinal velocity relative to the thermal one) stays positive. Strong dissipation
  // gets there through μ* (the heat flux driven by density gradients) outgrowing κ*.
  const int d = c.dimension;
  const double g = 1.0 + log_derivative_g2(d, c.packing_fraction);
  const double drive = c.cooling_rate * (c.pressure * g - 0.5 * c.compressibility);
  const double damping =
      c.compressibility * c.thermal_conductivity - c.pressure * c.heat_flux_density;
  return drive > 0.0 && damping <= 0.0;
}

double critical_box_size(const TransportCoefficients& c) {
  const double k = critical_shear_wavenumber(c);
  return k > 0 ? 2.0 * k_pi / k : std::numeric_limits<double>::infinity();
}

// Fluctuating hydrodynamics: the transverse momentum J of mode k relaxes as dJ/dt = −νk²J + ξ
// with noise ⟨ξξ*⟩ = 2NTνk² (fluctuation–dissipation at the local T, as van Noije, Ernst, Brito &
// Orza, PRL 79, 411 (1997)), ν = η/n. For S = ⟨|J|²⟩/(NT), with d(1/T)/dt = ζ/T:
// dS/dτ = 2λS + 2a, λ = (ζ/2 − νk²)/ω_E, a = νk²/ω_E, so S(τ) = (1 + a/λ)e^{2λτ} − a/λ; below
// k⊥ it grows without bound, above it tends to νk²/(νk² − ζ/2).
double transverse_structure_factor(const TransportCoefficients& c, double k, double tau) {
  const double ks = k * c.length_unit;
  const double a = c.shear_viscosity * ks * ks * c.collision_ratio;
  const double lambda = shear_mode_rate(c, k);
  if (std::abs(lambda) < 1e-14 * a) return 1.0 + 2.0 * a * tau;
  return (1.0 + a / lambda) * std::exp(2.0 * lambda * tau) - a / lambda;
}

double stationary_transverse_structure_factor(const TransportCoefficients& c, double k) {
  const double ks = k * c.length_unit;
  const double a = c.shear_viscosity * ks * ks * c.collision_ratio;
  const double lambda = shear_mode_rate(c, k);
  return lambda < 0 && std::abs(lambda) >= 1e-14 * a ? -a / lambda
                                                     : std::numeric_limits<double>::infinity();
}

double collisions_to_reach(const TransportCoefficients& c, double k, double level) {
  if (!(level > 1.0))
    throw std::invalid_argument("level: value " + std::to_string(level) +
                                " is outside the allowed range (1, inf)");
  const double ks = k * c.length_unit;
  const double a = c.shear_viscosity * ks * ks * c.collision_ratio;
  const double lambda = shear_mode_rate(c, k);
  if (std::abs(lambda) < 1e-14 * a) return (level - 1.0) / (2.0 * a);
  const double ratio = (level + a / lambda) / (1.0 + a / lambda);
  if (!(ratio > 0.0)) return std::numeric_limits<double>::infinity();
  const double tau = std::log(ratio) / (2.0 * lambda);
  return tau > 0 ? tau : std::numeric_limits<double>::infinity();
}

}  // namespace molchaos::theory
