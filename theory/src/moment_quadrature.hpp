// The two quadratures of the collision integrals over the relative velocity: fixed Gauss rules
// (exact for the polynomial-times-Gaussian integrand, the default) and nested adaptive GSL QAGIU
// (the independent check). Internal to molchaos::theory.
#pragma once

#include <array>
#include <cstddef>

#include "collision_integrand.hpp"
#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/estimate.hpp"

namespace molchaos::theory::detail {

struct TermIntegrals {
  std::array<Estimate, k_term_count> terms{};  ///< the integral of each term, prefactor included
  std::size_t evaluations = 0;                 ///< centre-of-mass sums evaluated
};

/// Every term's integral at once (the terms beyond a2, b are zero unless spec.with_a3).
/// Gauss: one pass of the product rule per order. Adaptive: one nested integral per term.
TermIntegrals integrate_terms(const IntegrandSpec& spec, const QuadratureOptions& options);

/// The integral of Σ_T multiplier[T]·term_T (e.g. the monomials a2^i a3^j b^k at given values).
Estimate integrate_combination(const IntegrandSpec& spec, const TermSums& multipliers,
                               const QuadratureOptions& options);

}  // namespace molchaos::theory::detail
