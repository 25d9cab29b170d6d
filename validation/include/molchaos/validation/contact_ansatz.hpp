// Collision averages at contact predicted by the paper's two-particle distribution (its Eq.
// (14) reduced at contact) and by its two-amplitude generalisation, in closed form:
//   f2 = f f g2 [1 + β∥ (c1·e)(c2·e) + β⊥ (c1·c2 − (c1·e)(c2·e))],
// the printed dyad b(κ(c1·e)(c2·e) − c1·c2) being β∥ = (κ − 1) b, β⊥ = −b (κ = 3 printed, κ = d
// traceless). Derivation and sympy check: theory/derivations/contact_correlations.py.
#pragma once

namespace molchaos::validation {

/// The four contact quantities, each a collision average (weight Θ(−c12·e)|c12·e|), c = v/√(2T):
/// P = ⟨(c1·e)(c2·e)⟩, Q = ⟨c1·c2⟩, W = ω/ω_Enskog, Y = ⟨(v12·e)²⟩/(4T).
struct ContactQuantities {
  double P = 0.0, Q = 0.0, W = 0.0, Y = 0.0;
};

/// Molecular chaos (β∥ = β⊥ = 0) with the Sonine coefficient a2, to first order in a2 (any d):
/// P = Q = −1/4 + a2/16, W = 1 − a2/16, Y = 1 + a2/4 (so W·Y = 1 + 3a2/16, μ2's a2 term).
ContactQuantities molecular_chaos_contact(double a2);

/// Molecular chaos with f = φ(1 + a2 S2 + a3 S3) in full (the product f(c1)f(c2), no
/// linearisation), the same rational functions for d = 2 and 3. With D = 16384 − 1024a2 − 256a3 −
/// 240a2² − 280a2a3 − 105a3²: W = D/16384, P = Q = −(16384 − 5120a2 − 1792a3 + 912a2² + 760a2a3
/// + 315a3²)/(4D), Y = (16384 + 3072a2 + 256a3 + 144a2² + 120a2a3 + 35a3²)/D; so
/// P = −1/4 + a2/16 + 3a3/128 − 7a2²/512 − 55a2a3/4096 + …
ContactQuantities molecular_chaos_contact_sonine(double a2, double a3);

/// ∂/∂β∥ and ∂/∂β⊥ of the four quantities at a2 = 0 (exact, linear order in the amplitudes):
/// ∂/∂β∥: P 3/8, Q 3/8, W −1/4, Y −1/2;  ∂/∂β⊥: P 0, Q (d − 1)/4, W 0, Y 0.
ContactQuantities slopes_longitudinal(int dimension);
ContactQuantities slopes_transverse(int dimension);

/// ∂/∂b of the four quantities for the printed-form dyad with factor κ: (κ − 1)∂/∂β∥ − ∂/∂β⊥.
/// κ = 3, d = 2: P 3/4, Q 1/2, W −1/2, Y −1 (d ln(W·Y)/db = −3/2, the cooling rate's b term).
ContactQuantities slopes_dyad(int dimension, double dyad_factor);

}  // namespace molchaos::validation
