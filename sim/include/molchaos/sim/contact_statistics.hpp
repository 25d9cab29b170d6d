// The per-collision accumulator of the contact statistics: the pre-collision reduced velocities
// c = v/√(2T) of a colliding pair projected on the contact normal, summed into ContactMoments,
// and the impact-parameter histogram. Called by the engine once per collision, before the rule.
#pragma once

#include <algorithm>
#include <cmath>

#include "molchaos/sim/result.hpp"

namespace molchaos::sim {

/// Adds one collision to m. vi, vj: pre-collision velocities of the pair; e: unit vector from j
/// to i at contact; temperature: T = ⟨v²⟩/d of the gas at the collision, in the velocities' units.
/// The impact parameter s = (1 − (ĝ·e)²)^((d−1)/2) is uniform on [0, 1) for any velocity
/// distribution when the contact normal is independent of the velocities (the flux through a
/// disk's cross-section is uniform in the impact distance, a sphere's in its square).
template <int D>
inline void accumulate(ContactMoments& m, const double* vi, const double* vj, const double* e,
                       double temperature) {
  static_assert(D == 2 || D == 3, "impact parameter defined for disks and spheres");
  const double scale = 1.0 / std::sqrt(2.0 * temperature);
  double c1e = 0, c2e = 0, c12 = 0, g2 = 0;
  for (int a = 0; a < D; ++a) {
    c1e += vi[a] * e[a];
    c2e += vj[a] * e[a];
    c12 += vi[a] * vj[a];
    g2 += (vi[a] - vj[a]) * (vi[a] - vj[a]);
  }
  const double gn_raw = c1e - c2e;
  c1e *= scale;
  c2e *= scale;
  const double gne = c1e - c2e;
  ++m.count;
  m.sum_c1e_c2e += c1e * c2e;
  m.sum_c1_dot_c2 += c12 * scale * scale;
  m.sum_gn2 += gne * gne;
  m.sum_abs_gn += std::fabs(gne);
  m.sum_g2 += g2 * scale * scale;
  const double sin2 = g2 > 0 ? std::max(0.0, 1.0 - gn_raw * gn_raw / g2) : 0.0;
  const double s = D == 2 ? std::sqrt(sin2) : sin2;
  const int bin = std::min(ContactMoments::k_impact_bins - 1,
                           static_cast<int>(s * ContactMoments::k_impact_bins));
  ++m.impact_histogram[static_cast<std::size_t>(bin)];
}

}  // namespace molchaos::sim
