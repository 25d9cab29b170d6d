// Fixed Gauss rules for the Gaussian-weighted integrals of kinetic theory: Gauss–Hermite for the
// centre-of-mass velocity and generalised Gauss–Laguerre for the squared speeds. A rule of order n
// integrates a polynomial of degree ≤ 2n − 1 against its weight exactly (Golub–Welsch, via GSL).
#pragma once

#include <vector>

namespace molchaos::theory {

struct GaussRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};

/// ∫_{−∞}^{∞} dx e^{−scale·x²} P(x) ≈ Σ w_k P(x_k).
GaussRule gauss_hermite_rule(int order, double scale);

/// ∫_0^∞ dx x^α e^{−x} P(x) ≈ Σ w_k P(x_k), α > −1.
GaussRule gauss_laguerre_rule(int order, double alpha);

/// The smallest order whose rule is exact for polynomials of the given degree.
inline int exact_gauss_order(int degree) { return degree / 2 + 1; }

}  // namespace molchaos::theory
