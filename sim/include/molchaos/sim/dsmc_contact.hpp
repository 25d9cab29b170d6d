// The contact vector of a DSMC collision: e drawn with weight Θ(−g·e)|g·e| on the unit sphere,
// which is the same as an impact parameter drawn uniformly over the collision cross-section.
#pragma once

#include <cmath>

#include "molchaos/sim/rng.hpp"

namespace molchaos::sim {

/// ∫de Θ(−ĝ·e)|ĝ·e| over the unit sphere S^{d−1}: the volume of the unit (d−1)-ball, 2 (d = 2,
/// ∫cos θ dθ over (−π/2, π/2)) and π (d = 3, ∫cos θ sin θ dθ dφ over the hemisphere). The collision
/// rate of a pair is n g2 σ^{d−1} β_d |g| per unit density, so that the per-particle frequency is
/// n g2 β_d ⟨|g|⟩ = 2 n g2 √(πT) (disks) and 4 n g2 √(πT) (spheres), Enskog's.
template <int D>
inline constexpr double k_cross_section = D == 2 ? 2.0 : 3.14159265358979323846;

/// Draws e, the unit vector from j to i at contact, for relative velocity g = v_i − v_j with
/// |g| = g_norm > 0, with density Θ(−g·e)|g·e| / (β_d |g|).
///
/// Why an impact parameter: write e = b − √(1 − b²) ĝ with b ⊥ ĝ. Projecting the approaching
/// hemisphere onto the plane ⊥ ĝ has Jacobian |ĝ·e| (de = db / |ĝ·e|), so a b uniform in the unit
/// (d−1)-ball gives e exactly the weight |ĝ·e|: in 2D b is uniform in [−1, 1] (flat impact
/// parameter), in 3D uniform in the unit disk (|b|² = sin²θ uniform in [0, 1]).
template <int D>
inline void draw_contact_direction(const double* g, double g_norm, Rng& rng, double* e) {
  const double inv = 1.0 / g_norm;
  if constexpr (D == 2) {
    const double gx = g[0] * inv, gy = g[1] * inv;
    const double b = 2.0 * rng.uniform() - 1.0;
    const double normal = std::sqrt(1.0 - b * b);
    // b along the perpendicular (−ĝ_y, ĝ_x).
    e[0] = -b * gy - normal * gx;
    e[1] = b * gx - normal * gy;
  } else {
    const double n[3] = {g[0] * inv, g[1] * inv, g[2] * inv};
    double p1, p2, q;
    do {  // uniform in the unit disk by rejection from the square (acceptance π/4)
      p1 = 2.0 * rng.uniform() - 1.0;
      p2 = 2.0 * rng.uniform() - 1.0;
      q = p1 * p1 + p2 * p2;
    } while (q >= 1.0);
    // An orthonormal pair (t1, t2) ⊥ ĝ without branches on the direction of ĝ (Duff et al.,
    // "Building an orthonormal basis, revisited", JCGT 6(1), 2017).
    const double sign = std::copysign(1.0, n[2]);
    const double a = -1.0 / (sign + n[2]);
    const double b = n[0] * n[1] * a;
    const double t1[3] = {1.0 + sign * n[0] * n[0] * a, sign * b, -sign * n[0]};
    const double t2[3] = {b, sign + n[1] * n[1] * a, -n[1]};
    const double normal = std::sqrt(1.0 - q);
    for (int k = 0; k < 3; ++k) e[k] = p1 * t1[k] + p2 * t2[k] - normal * n[k];
  }
}

}  // namespace molchaos::sim
