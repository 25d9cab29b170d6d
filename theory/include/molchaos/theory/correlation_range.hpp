// The values of the paper's correlation coefficient b = χ(σ)/g2(σ) for which its ansatz
// f2 = f f g2 [1 + b D̂:c1c2] (Eq. (17)) describes a gas: the quantities f2 feeds into the
// suite (collision rate, cooling rate μ2, density of grazing collisions) stay positive.
// Derivation in doc/theory.md, section 6.
#pragma once

#include <string>

#include "molchaos/theory/collision_moments.hpp"

namespace molchaos::theory {

/// b ∈ [lower, upper).
struct CorrelationRange {
  double lower = 0.0;  ///< −4/(κ − 1): below it fewer than no grazing collisions occur
  /// Where μ2(a2, b) (or the collision rate) stops being positive beyond its error: μ2 no
  /// longer distinguishable from 0 gives no cooling time.
  double upper = 0.0;
  /// Uncertainty of the nominal zero (R0/(−R1) for μ2): `upper` lies this far below it, and no
  /// digit of `upper` finer than this means anything.
  double upper_error = 0.0;
};

/// The range at Sonine coefficient a2 and dyad factor κ (> 1), in dimension d.
/// `a2_error`: the uncertainty of a2 (cooling.hpp's CoolingPrediction::a2_error), carried into
/// the errors of μ2 and of the collision rate.
CorrelationRange correlation_b_range(int dimension, double a2, double dyad_factor,
                                     const QuadratureOptions& options = {}, double a2_error = 0.0);

/// The same from a μ2 expansion table already at hand (any ε < 1; its ratio does not depend on ε).
CorrelationRange correlation_b_range(const ExpansionTable& mu2_table, double a2,
                                     const QuadratureOptions& options = {}, double a2_error = 0.0);

/// "[lower, upper)" with `upper` to the digits its uncertainty supports, at most
/// `significant_digits` (cut, not rounded up).
std::string range_text(const CorrelationRange& range, int significant_digits = 17);

/// Throws std::invalid_argument naming `correlation_b` and the range unless b lies in it.
void require_correlation_b(const ExpansionTable& mu2_table, double a2, double b,
                           const QuadratureOptions& options = {}, double a2_error = 0.0);

}  // namespace molchaos::theory
