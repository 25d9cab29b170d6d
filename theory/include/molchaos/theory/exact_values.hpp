// Lookup of the exact collision-integral values that theory/derivations/collision_moments.py
// derives symbolically at build time (generated header exact_coefficients.hpp). They are the
// independent reference for the quadrature (tests, benchmarks) and the exact form `molchaos
// theory` prints beside each number; the suite's results always come from the quadrature.
#pragma once

#include <cmath>
#include <numbers>
#include <string_view>

#include "molchaos/theory/exact_coefficients.hpp"

namespace molchaos::theory::exact {

/// The term of μ_p (dyad factor κ ∈ {3, d}); nullptr if the derivation does not provide it.
inline const MomentTerm* find_moment_term(int dimension, int p, double dyad_factor,
                                          std::string_view term) {
  for (const MomentTerm& t : k_moment_terms)
    if (t.dimension == dimension && t.moment == p && t.dyad_factor == dyad_factor && term == t.term)
      return &t;
  return nullptr;
}

/// The contact average `quantity` ("normal_product", "velocity_product", "dyad",
/// "collision_frequency_ratio", "dissipation_ratio", "collision_integral_J1").
inline const ContactTerm* find_contact_term(int dimension, double dyad_factor,
                                            std::string_view quantity) {
  for (const ContactTerm& t : k_contact_terms)
    if (t.dimension == dimension && t.dyad_factor == dyad_factor && quantity == t.quantity)
      return &t;
  return nullptr;
}

/// The term's integral at restitution ε: √(2π) Σ_k c_k ε^k.
inline double integral(const MomentTerm& t, double restitution) {
  double sum = 0.0;
  for (auto it = t.eps_polynomial.rbegin(); it != t.eps_polynomial.rend(); ++it)
    sum = sum * restitution + *it;
  return std::sqrt(2.0 * std::numbers::pi) * sum;
}

/// The coefficient of the term in μ_p/μ_p(0,0) at restitution ε.
inline double coefficient(const MomentTerm& t, double restitution) {
  const MomentTerm* base = find_moment_term(t.dimension, t.moment, t.dyad_factor, "1");
  return integral(t, restitution) / integral(*base, restitution);
}

}  // namespace molchaos::theory::exact
