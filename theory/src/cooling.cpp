// Haff's law prefactors and the kinetic-theory prediction for one state point.
#include "molchaos/theory/cooling.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/correlation_range.hpp"
#include "molchaos/theory/dimension.hpp"
#include "molchaos/theory/sonine.hpp"

namespace molchaos::theory {

double mu2_maxwell_prefactor(int dimension) {
  require_dimension(dimension);
  const double root_2pi = std::sqrt(2.0 * std::numbers::pi);
  return dimension == 2 ? 0.5 * root_2pi : root_2pi;
}

double cooling_frequency_omega0(int dimension, double density, double initial_temperature) {
  require_in_range("initial_temperature", initial_temperature, 0.0,
                   std::numeric_limits<double>::infinity(), true);
  const double g2 = contact_value_g2_at_density(dimension, density);
  return g2 * density * std::sqrt(2.0 * initial_temperature) * mu2_maxwell_prefactor(dimension) /
         dimension;
}

double enskog_collision_frequency(int dimension, double density, double temperature) {
  const double g2 = contact_value_g2_at_density(dimension, density);
  const double prefactor = dimension == 2 ? 2.0 : 4.0;
  return prefactor * density * g2 * std::sqrt(std::numbers::pi * temperature);
}

double omega0_relative_rounding(int dimension, double density) {
  // ω0 = g2 · n · √(2T0) · μ̂_d / d, each operation off by at most u (estimate.hpp): μ̂_d = ½√(2π)
  // or √(2π) (the rounded π, the root: 2u), √(2T0) (u), three products and the division (4u):
  // 7u. g2 (contact_value.cpp): η = n·(π/4 or π/6) is off by 3u; its numerator 1 − x
  // (x = 7η/16 or η/2, off by 4u) by u + 4u·x/(1 − x); its denominator (1 − η)^d by
  // d(u + 3u·η/(1 − η)) + 2u (the square's product, or pow); the quotient by u. In all,
  // u[7 + 4x/(1 − x) + 3d·η/(1 − η)] with d ≤ 3 over the 2 + 3u of the rest: the bound below.
  // The typed n's rounding to a double (u) moves n·g2 by u(1 − x/(1 − x) + d·η/(1 − η)) at
  // most, x/(1 − x) < 1: another u[1 + d·η/(1 − η)].
  const double eta = packing_fraction(dimension, density);
  const double x = dimension == 2 ? 7.0 * eta / 16.0 : 0.5 * eta;
  const double roundings = 15.0 + 4.0 * x / (1.0 - x) + 4.0 * dimension * eta / (1.0 - eta);
  return roundings * k_unit_roundoff;
}

Estimate cooling_prefactor_A(int dimension, double density, double initial_temperature,
                             const Estimate& mu2_ratio) {
  const double omega0 = cooling_frequency_omega0(dimension, density, initial_temperature);
  const double A = 1.0 / (omega0 * mu2_ratio.value);
  // Relative errors add: the ratio's, ω0's rounding, and the product and reciprocal (2u).
  const double relative = mu2_ratio.relative_error() +
                          omega0_relative_rounding(dimension, density) + 2.0 * k_unit_roundoff;
  return {A, std::abs(A) * relative};
}

double log_time_after_collisions(double collisions, double tau0,
                                 double initial_collision_frequency) {
  const double x = collisions / (initial_collision_frequency * tau0);
  // ln(e^x − 1): directly while e^x − 1 is well inside a double (expm1 keeps small x exact),
  // else as x + ln(1 − e^{−x}), whose log1p term is tiny and exact.
  const double log_expm1 = x < 1.0 ? std::log(std::expm1(x)) : x + std::log1p(-std::exp(-x));
  return std::log(tau0) + log_expm1;
}

CoolingPrediction predict_cooling(const CoolingInputs& in) {
  require_dimension(in.dimension);
  require_density(in.dimension, in.density);
  require_restitution(in.restitution);
  if (in.quadrature.method != QuadratureMethod::gauss) {
    // The inputs' checks (the allowed b, A and τ0 within a double) by the exact Gauss rules
    // first, in milliseconds: the adaptive quadrature takes seconds before it reaches them.
    CoolingInputs screen = in;
    screen.quadrature = QuadratureOptions{};
    predict_cooling(screen);
  }
  CoolingPrediction out;
  out.packing_fraction = packing_fraction(in.dimension, in.density);
  out.g2 = contact_value_g2(in.dimension, out.packing_fraction);
  out.a2 = in.a2 ? *in.a2 : a2_first_sonine(in.dimension, in.restitution);
  out.omega0 = cooling_frequency_omega0(in.dimension, in.density, in.initial_temperature);
  out.enskog_collision_frequency =
      enskog_collision_frequency(in.dimension, in.density, in.initial_temperature);

  // One table of μ2's terms (exact Gauss rules, or adaptive when asked). Every term is ∝ 1 − ε²
  // (Δ(c1² + c2²) is), so the table is taken at ε = 1/2 and its base scaled by
  // (1 − ε)(1 + ε)/(3/4): a table at ε itself loses digits to cancellation as ε → 1 (μ2 came out
  // negative at ε = 1 − 2⁻⁵³), and at ε = 1 every term vanishes. (1 − ε)(1 + ε) rather than
  // 1 − ε², whose rounding of ε² is a relative error of 1e-16/(1 − ε²).
  constexpr double k_eps_table = 0.5;
  const double one_minus_eps2 = (1.0 - in.restitution) * (1.0 + in.restitution);
  const double base_scale = one_minus_eps2 / ((1.0 - k_eps_table) * (1.0 + k_eps_table));
  const ExpansionTable table =
      expand_collision_moment(in.dimension, 2, k_eps_table, in.dyad_factor, in.quadrature);
  // The closed form of a2 is exact, but the suite vouches for it only as far as its own
  // quadrature of the same moment equation confirms it: that error is carried, so that A here
  // and A at the first_sonine level (sonine_hcs.hpp, shown beside it) carry one error. By the
  // Gauss rules whatever the method (the adaptive μ4 table would double the time).
  if (!in.a2) out.a2_error = a2_from_moments(in.dimension, in.restitution).error;
  require_correlation_b(table, out.a2, in.correlation_b, in.quadrature, out.a2_error);
  out.mu2_ratio = table.ratio_estimate(PairShape{out.a2, 0.0, in.correlation_b}, out.a2_error);
  const Estimate ratio_uncorrelated =
      table.ratio_estimate(PairShape{out.a2, 0.0, 0.0}, out.a2_error);
  // μ2 and τ0 are ∝ (1 − ε²)^{±1}: the typed ε's rounding to a double (input_rounding) moves
  // them by 2ε/(1 − ε²) times it, relative: 5e-11 at ε = 0.999999, far beyond the quadrature.
  const double eps_relative_shift =
      in.restitution < 1.0 ? 2.0 * in.restitution / one_minus_eps2 * input_rounding(in.restitution)
                           : 0.0;
  if (in.restitution < 1.0) {
    const double base = table.base.value * base_scale;
    // Beyond the quadrature: base_scale (1 − ε, 1 + ε, their product, the division: 4u) and the
    // two products (2u).
    const double value = base * out.mu2_ratio.value;
    out.mu2 = {value, std::abs(base) * out.mu2_ratio.error +
                          table.base.error * base_scale * std::abs(out.mu2_ratio.value) +
                          rounding_bound(value, 6.0) + std::abs(value) * eps_relative_shift};
  } else {
    out.mu2 = {0.0, 0.0};  // elastic: no dissipation, exactly
  }

  // A = 1/(ω0 μ2/μ2(0,0)): independent of ε except through a2 and b.
  out.A = cooling_prefactor_A(in.dimension, in.density, in.initial_temperature, out.mu2_ratio);
  out.A_uncorrelated =
      cooling_prefactor_A(in.dimension, in.density, in.initial_temperature, ratio_uncorrelated);
  if (in.restitution < 1.0) {
    // τ0 = A/((1 − ε)(1 + ε)): the factors, their product and the division add 4u (1 − ε is
    // exact for ε ≥ ½, counted anyway).
    const double tau0 = out.A.value / one_minus_eps2;
    out.tau0 = {tau0, std::abs(tau0) *
                          (out.A.relative_error() + 4.0 * k_unit_roundoff + eps_relative_shift)};
  } else {
    out.tau0 = {std::numeric_limits<double>::infinity(), 0.0};
  }
  // A and τ0 ∝ 1/(n g2): at a tiny density they overflow a double (τ0 at ε = 1 is infinite by
  // physics, A is not). Refused here, where they are computed, so that no caller prints inf.
  const bool tau0_overflows = in.restitution < 1.0 && !std::isfinite(out.tau0.value);
  if (!std::isfinite(out.A.value) || tau0_overflows) {
    // The smallest density with finite A and τ0, from n = 1e-6, where g2 is 1 to a part in a
    // million and both are ∝ 1/n.
    CoolingInputs reference = in;
    reference.density = 1e-6;
    const CoolingPrediction r = predict_cooling(reference);
    const double largest = in.restitution < 1.0 ? r.tau0.value : r.A.value;
    std::ostringstream msg;
    msg << "density: value " << exact_text(in.density) << " is outside the allowed range ("
        << std::setprecision(3) << reference.density * largest / std::numeric_limits<double>::max()
        << ", " << exact_text(close_packing_density(in.dimension)) << ") for restitution "
        << exact_text(in.restitution)
        << (in.restitution < 1.0 ? ": below it the cooling time τ0 ∝ 1/n overflows a double"
                                 : ": below it the prefactor A ∝ 1/n overflows a double");
    throw std::invalid_argument(msg.str());
  }
  return out;
}

}  // namespace molchaos::theory
