// The variation points of a collision, as tiny evaluators (a value with its parameters and one
// `apply`): the collision rule (constant restitution, paper eq. (coll) inverted), the TC model
// that makes it elastic for recent colliders, and the velocity shuffles that follow it (Sec. 4).
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>

#include "molchaos/sim/rng.hpp"

namespace molchaos::sim {

/// Constant coefficient of restitution. With e the unit vector from j to i at contact and
/// g = v_i - v_j (g.e < 0 approaching): v_i' = v_i - (1+eps)/2 (g.e) e, v_j' = v_j + (1+eps)/2
/// (g.e) e. Energy lost (m = 1): (1 - eps^2)/4 (g.e)^2.
struct ConstantRestitution {
  double restitution = 1.0;

  /// Applies the rule to the approaching pair with normal velocity `normal_velocity` = g.e (as the
  /// engine computed it for its approach test); eps = 1 when `elastic` (the TC model), else
  /// `restitution`. Returns the kinetic energy lost, (1 - eps^2)/4 (g.e)^2.
  template <int D>
  double apply(double* vi, double* vj, const double* e, double normal_velocity,
               bool elastic) const {
    const double eps = elastic ? 1.0 : restitution;
    double gn = 0, ee = 0;
    for (int a = 0; a < D; ++a) {
      gn += (vi[a] - vj[a]) * e[a];
      ee += e[a] * e[a];
    }
    // Dividing by e.e (1 up to rounding) makes the energy change -(1 - eps^2)/4 (g.e)^2/(e.e)
    // exact for any length of e: without it the rounding of the normalised e biases the energy
    // of every elastic collision upwards by a few ulp, a drift of 1e-19 N per collision.
    const double kick = 0.5 * (1.0 + eps) * gn / ee;
    for (int a = 0; a < D; ++a) {
      vi[a] -= kick * e[a];
      vj[a] += kick * e[a];
    }
    return 0.25 * (1.0 - eps * eps) * normal_velocity * normal_velocity;
  }
};

/// The TC model (Luding & McNamara, Granular Matter 1, 113 (1998)): a collision is elastic when
/// one of the pair collided less than `duration` ago (physical time), which keeps the collision
/// rate finite where an inelastic gas would collapse. duration = 0: off.
struct TcModel {
  double duration = 0.0;

  bool apply(double time_since_last_collision) const {
    return duration > 0 && time_since_last_collision < duration;
  }
};

template <int D>
void exchange_velocities(double* vi, double* vj, double* vk, double* vl, const double* e);

/// No shuffle: the plain inelastic gas.
struct NoShuffle {
  static constexpr bool active = false;
};

/// A shuffle's one `apply`: picks the donor pair (k, l), lets the caller bring k and l to the
/// present (`prepare(k, l)`: their positions move with their old velocities), then exchanges the
/// velocities (exchange_velocities). velocity(m) is a pointer to particle m's D components;
/// `temperature` is in the units of those velocities. Returns (k, l).
template <int D, class Shuffle, class Velocity, class Prepare>
std::pair<std::int32_t, std::int32_t> apply_shuffle(const Shuffle& shuffle,
                                                    const Velocity& velocity, std::int32_t n,
                                                    std::int32_t i, std::int32_t j, const double* e,
                                                    double temperature, Rng& rng,
                                                    const Prepare& prepare) {
  const auto [k, l] = shuffle.template pick<D>(velocity, n, i, j, e, temperature, rng);
  prepare(k, l);
  exchange_velocities<D>(velocity(i), velocity(j), velocity(k), velocity(l), e);
  return {k, l};
}

/// The paper's shuffle: two distinct random particles k, l not in {i, j}, drawn uniformly.
struct PaperShuffle {
  static constexpr bool active = true;

  /// velocity(k) returns a pointer to the D components of particle k's velocity.
  template <int D, class Velocity>
  std::pair<std::int32_t, std::int32_t> pick(const Velocity& /*velocity*/, std::int32_t n,
                                             std::int32_t i, std::int32_t j, const double* /*e*/,
                                             double /*temperature*/, Rng& rng) const {
    std::int32_t k, l;
    do k = static_cast<std::int32_t>(rng.below(n));
    while (k == i || k == j);
    do l = static_cast<std::int32_t>(rng.below(n));
    while (l == i || l == j || l == k);
    return {k, l};
  }
};

/// A shuffle that keeps molecular chaos *and* the equilibrium of an elastic gas.
///
/// Why the paper's shuffle is not enough: in equilibrium the pairs leaving a collision with normal
/// e have velocities distributed as f(v1) f(v2) |g.e| Theta(g.e > 0): the collision flux weights
/// each pair by its normal relative speed (the length of its collision cylinder), and for elastic
/// collisions the outgoing flux mirrors the incoming one. The paper hands the separating pair the
/// velocities of a uniformly drawn pair, distributed as f f only, so separating pairs leave contact
/// too slowly on average: the density of outgoing pairs at contact, flux / |g.e|, becomes
/// proportional to f f / |g.e|, which is not the equilibrium g2 f f (it even diverges
/// logarithmically for grazing departures). Pairs linger at contact, a third particle pushes them
/// together again, and the collision frequency exceeds Enskog's.
///
/// The fix: draw (k, l) uniformly, accept with probability min(1, |(v_k - v_l).e| / G) and redraw
/// on rejection. The accepted pair is distributed as f f |g.e|, the equilibrium post-collision
/// flux; orienting it to separate gives exactly the equilibrium outgoing pair, and k, l (far away,
/// uncorrelated) receive v_i', v_j'. The velocity multiset changes only by the collision itself, as
/// in the paper. G = 5 sqrt(2T) (the normal relative speed has variance 2T): pairs with |g.e| > G
/// are accepted with probability 1 instead of |g.e|/G, a bias on a fraction ~1e-6 of the flux.
struct FluxShuffle {
  static constexpr bool active = true;
  double bound_in_thermal_units = 5.0;

  template <int D, class Velocity>
  std::pair<std::int32_t, std::int32_t> pick(const Velocity& velocity, std::int32_t n,
                                             std::int32_t i, std::int32_t j, const double* e,
                                             double temperature, Rng& rng) const {
    const double bound = bound_in_thermal_units * std::sqrt(2.0 * temperature);
    const PaperShuffle uniform_pair;
    for (;;) {
      const auto [k, l] = uniform_pair.pick<D>(velocity, n, i, j, e, temperature, rng);
      const double* vk = velocity(k);
      const double* vl = velocity(l);
      double gn = 0;
      for (int a = 0; a < D; ++a) gn += (vk[a] - vl[a]) * e[a];
      if (rng.uniform() * bound < std::fabs(gn)) return {k, l};
    }
  }
};

/// The exchange common to both shuffles: i and j receive the velocities of k and l, assigned so
/// that the pair (i, j) separates along e ((v_i - v_j).e > 0), and each donor takes the
/// post-collision velocity of the particle it gave its own to (a pairwise exchange). The paper
/// does not say which donor takes which; giving v_i' to k and v_j' to l in the order drawn instead
/// raises the collision frequency at ε = 1 by 0.3 % (doc/validation.md).
template <int D>
void exchange_velocities(double* vi, double* vj, double* vk, double* vl, const double* e) {
  double gn = 0;
  for (int a = 0; a < D; ++a) gn += (vk[a] - vl[a]) * e[a];
  if (gn < 0) std::swap(vk, vl);  // now (vk - vl).e >= 0: i <- vk, j <- vl separates
  for (int a = 0; a < D; ++a) {
    const double ui = vi[a], uj = vj[a];
    vi[a] = vk[a];
    vj[a] = vl[a];
    vk[a] = ui;
    vl[a] = uj;
  }
}

}  // namespace molchaos::sim
