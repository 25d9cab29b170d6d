// How the paper's correlated pair distribution at contact, f2 = f f g2 [1 + b D̂:c1c2]
// (Eqs. (14), (17); D̂ = κ ee − U), shows in averages over colliding pairs: to first
// order in b and a2 (with the a2·b cross term), the coefficients that turn measured contact
// statistics into b. Velocities are reduced, c = v/√(2T); "colliding" means approaching pairs at
// contact weighted by the collision rate Θ(−c12·e)|c12·e|.
#pragma once

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/estimate.hpp"

namespace molchaos::theory {

/// X(a2, b) = value + d_a2·a2 + d_b·b + d_a2b·a2·b + O(a2², b²).
struct ResponseSeries {
  Estimate value, d_a2, d_b, d_a2b;
  [[nodiscard]] double at(double a2, double b) const {
    return value.value + d_a2.value * a2 + d_b.value * b + d_a2b.value * a2 * b;
  }
};

struct ContactResponse {
  int dimension = 2;
  double dyad_factor = k_paper_dyad_factor;
  ResponseSeries normal_product;    ///< ⟨(c1·e)(c2·e)⟩_coll (−1/4 for molecular chaos)
  ResponseSeries velocity_product;  ///< ⟨c1·c2⟩_coll (−1/4 for molecular chaos)
  ResponseSeries dyad;              ///< ⟨D̂:c1c2⟩_coll = κ·normal − velocity product
  ResponseSeries collision_frequency_ratio;  ///< ω/ω_Enskog (ω_Enskog: a2 = b = 0)
  ResponseSeries dissipation_ratio;  ///< ⟨(c12·e)²⟩_coll / ⟨(c12·e)²⟩_coll at a2 = b = 0
};

/// The coefficients for dyad factor κ (3 as printed, d for the traceless dyad) in dimension d.
ContactResponse contact_response(int dimension, double dyad_factor,
                                 const QuadratureOptions& options = {});

}  // namespace molchaos::theory
