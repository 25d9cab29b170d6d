// The Sonine coefficients a2, a3 of the homogeneous cooling state beyond the first Sonine
// approximation, and the cooling-rate factor μ2(a2, a3)/μ2(0,0) that follows, for d = 2, 3.
//
// The scaled homogeneous cooling state obeys μ_p = (p/d) μ2 ⟨c^p⟩ (second moment of the scaled
// Enskog–Boltzmann equation), with ⟨c⁴⟩ = d(d+2)/4 (1 + a2) and ⟨c⁶⟩ = d(d+2)(d+4)/8 (1 + 3a2 − a3)
// for f̃ = φ(1 + a2 S2 + a3 S3):
//     F4 = μ4 − (d + 2)(1 + a2) μ2 = 0,     F6 = μ6 − ¾(d + 2)(d + 4)(1 + 3a2 − a3) μ2 = 0,
// where μ2, μ4, μ6 are the exact quadratic polynomials in (a2, a3) whose terms the quadrature
// gives. Four levels of theory (Brilliantov & Pöschel, Phys. Rev. E 61 (2000), keep a2²; the
// third coefficient enters through μ6):
//   first_sonine   a3 = 0, F4 linearised in a2 (van Noije & Ernst; the paper's Eq. (25))
//   a2_nonlinear   a3 = 0, F4 solved in full (a cubic; the root continuing the linear one)
//   a2_a3_linear   F4 and F6 linearised in (a2, a3)
//   a2_a3          F4 and F6 solved in full (Newton from the linear solution)
#pragma once

#include <string>

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/estimate.hpp"

namespace molchaos::theory {

struct SonineSolution {
  std::string level;   ///< "first_sonine", "a2_nonlinear", "a2_a3_linear", "a2_a3"
  Estimate a2;         ///< error: the quadrature's, propagated through the equations
  Estimate a3;         ///< 0 exactly where a3 is not part of the level
  Estimate mu2_ratio;  ///< μ2(a2, a3)/μ2(0,0), b = 0
  Estimate A_omega0;   ///< A·ω0 = μ2(0,0)/μ2(a2, a3): the factor by which A changes
};

struct HcsSonine {
  SonineSolution first_sonine, a2_nonlinear, a2_a3_linear, a2_a3;
};

/// All four levels at restitution ε ∈ (0, 1] in dimension d.
HcsSonine hcs_sonine_coefficients(int dimension, double restitution,
                                  const QuadratureOptions& options = {});

}  // namespace molchaos::theory
