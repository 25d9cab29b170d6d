// Closed forms of contact_ansatz.hpp (theory/derivations/contact_correlations.py prints them).
//
// With c1 = C + g/2, c2 = C − g/2 and e along x, Maxwell pairs weighted by the collision flux have
// independent Gaussian C (variance 1/4 per component), transverse g (variance 1) and approach
// speed u = −g·e with density u e^{−u²/2}; so P = C_x² − u²/4, Q = P − C⊥² + g⊥²/4, Y = u²/2.
// An amplitude β of a factor (1 + β X) shifts a collision average ⟨Z⟩ by β·cov(Z, X) and W by
// β⟨X⟩: cov(P, P) = var C_x² + var u²/16 = 1/8 + 1/4, cov(P, Q − P) = 0,
// cov(Q, Q − P) = var C⊥² + var g⊥²/16 = (d − 1)/4, cov(u²/2, P) = −var(u²)/8 = −1/2.
#include "molchaos/validation/contact_ansatz.hpp"

namespace molchaos::validation {

ContactQuantities molecular_chaos_contact(double a2) {
  return {-0.25 + a2 / 16.0, -0.25 + a2 / 16.0, 1.0 - a2 / 16.0, 1.0 + a2 / 4.0};
}

ContactQuantities molecular_chaos_contact_sonine(double a2, double a3) {
  // theory/derivations/contact_correlations.py, molecular_chaos_sonine(d).
  const double den =
      16384.0 - 1024.0 * a2 - 256.0 * a3 - 240.0 * a2 * a2 - 280.0 * a2 * a3 - 105.0 * a3 * a3;
  const double p =
      -(16384.0 - 5120.0 * a2 - 1792.0 * a3 + 912.0 * a2 * a2 + 760.0 * a2 * a3 + 315.0 * a3 * a3) /
      (4.0 * den);
  const double y =
      (16384.0 + 3072.0 * a2 + 256.0 * a3 + 144.0 * a2 * a2 + 120.0 * a2 * a3 + 35.0 * a3 * a3) /
      den;
  return {p, p, den / 16384.0, y};
}

ContactQuantities slopes_longitudinal(int /*dimension*/) {
  return {3.0 / 8.0, 3.0 / 8.0, -0.25, -0.5};
}

ContactQuantities slopes_transverse(int dimension) {
  return {0.0, (dimension - 1) / 4.0, 0.0, 0.0};
}

ContactQuantities slopes_dyad(int dimension, double dyad_factor) {
  const ContactQuantities l = slopes_longitudinal(dimension), t = slopes_transverse(dimension);
  const double k = dyad_factor - 1.0;
  return {k * l.P - t.P, k * l.Q - t.Q, k * l.W - t.W, k * l.Y - t.Y};
}

}  // namespace molchaos::validation
