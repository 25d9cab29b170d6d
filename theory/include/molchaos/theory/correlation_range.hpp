// The values of the paper's correlation coefficient b = χ(σ)/g2(σ) for which its ansatz
// f2 = f f g2 [1 + b D̂:c1c2] (eq. f2atsigma) describes a gas: the quantities f2 feeds into the
// suite (collision rate, cooling rate μ2, density of grazing collisions) stay positive.
// Derivation in doc/theory.md, section 6.
#pragma once

#include "molchaos/theory/collision_moments.hpp"

namespace molchaos::theory {

/// b ∈ [lower, upper).
struct CorrelationRange {
  double lower = 0.0;  ///< −4/(κ − 1): below it fewer than no grazing collisions occur
  double upper = 0.0;  ///< where μ2(a2, b) (or the collision rate) reaches zero
};

/// The range at Sonine coefficient a2 and dyad factor κ (> 1), in dimension d.
CorrelationRange correlation_b_range(int dimension, double a2, double dyad_factor,
                                     const QuadratureOptions& options = {});

/// The same from a μ2 expansion table already at hand (any ε < 1; its ratio does not depend on ε).
CorrelationRange correlation_b_range(const ExpansionTable& mu2_table, double a2,
                                     const QuadratureOptions& options = {});

/// Throws std::invalid_argument naming `correlation_b` and the range unless b lies in it.
void require_correlation_b(const ExpansionTable& mu2_table, double a2, double b,
                           const QuadratureOptions& options = {});

}  // namespace molchaos::theory
