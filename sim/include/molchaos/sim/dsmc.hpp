// Direct simulation Monte Carlo (Bird) of the spatially homogeneous Enskog–Boltzmann equation for
// inelastic hard disks and spheres: N velocities and no positions, so that the velocities of a
// colliding pair are uncorrelated by construction (molecular chaos), beside the event-driven MD.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "molchaos/sim/collision.hpp"
#include "molchaos/sim/parameters.hpp"
#include "molchaos/sim/result.hpp"
#include "molchaos/sim/rng.hpp"
#include "molchaos/sim/run.hpp"

namespace molchaos::sim {

/// The N-particle Kac master equation whose mean-field limit is the homogeneous Enskog–Boltzmann
/// equation. Every pair (i, j) collides at rate k|g_ij|, k = g2 β_d / V = n g2 β_d / N (β_d in
/// dsmc_contact.hpp): the rate of a pair of the MD's N disks or spheres in the volume V = N/n
/// (σ = m = 1) without correlations, so that each particle meets N − 1 partners at the density
/// (N − 1)/V, as in the MD, and the two methods at equal N differ by the pair correlations alone
/// (with k = n g2 β_d/(N − 1), Enskog's ω at any N, DSMC collided N/(N − 1) times as often as the
/// MD gas, and its A fell 1/N below the MD's: 5 % at N = 20). The mean per-particle frequency
/// is (N − 1)/N · n g2 β_d ⟨|g|⟩ over pairs, Enskog's ω as N → ∞; e is drawn with weight
/// Θ(−g·e)|g·e|, and the rule is the MD's CollisionRule::apply.
///
/// Exact by thinning: candidate pairs come uniformly at the majorant rate Λ = k·2B·N(N − 1)/2 and
/// are accepted with probability |g|/(2B), where B ≥ max_i |v_i| is raised right after any
/// collision that exceeds it, so that 2B ≥ |g| holds for every pair at every step (unlike the
/// classic no-time-counter scheme, which raises its bound only after a candidate exceeded it and
/// so under-weights the fastest pairs). Waiting times between candidates are exponential with
/// the current Λ: their sum is −ln Π u_k / Λ, so the hot loop multiplies uniforms and takes one
/// logarithm only when Λ changes or the product nears underflow. A stop time (a sample time)
/// that a candidate's time passes leaves that candidate pending, its waiting time in the product,
/// and the next advance_to() goes on with it: the realisation does not depend on where a run is
/// sampled (--samples-per-decade, --t-first-sample), as the MD engine's does not.
/// A candidate's waiting-time and acceptance uniforms have 32 bits each (one generator call):
/// probabilities are then resolved to 2^-32, far below any statistical error a run reaches.
///
/// Internal units: velocities u = s·v are rescaled by s → s/√T_internal whenever the internal
/// temperature falls below 1/4 (checked every N/4 collisions), so numbers stay O(1) in long
/// cooling runs; the physical time is accumulated directly.
template <int D>
class DsmcGas {
 public:
  enum class Status { reached, stopped };

  /// Maxwell velocities with zero momentum and T = 1 exactly, drawn from Rng(p.seed); the
  /// collisions use a second stream. contact_value_g2 is Enskog's factor at p.density (an input:
  /// the sim library does not depend on the theory library; run_dsmc passes contact_value_g2()
  /// of run.hpp, the tests check it against the theory's).
  DsmcGas(const Parameters& p, double contact_value_g2);

  /// Runs until the physical time t (Status::reached) or a stop condition (max_collisions,
  /// min_temperature; Status::stopped, stop_reason() says which).
  Status advance_to(double t);

  /// T, a2 and the contact sums since the previous sample (which it resets); velocity_mode and
  /// density_mode are NaN (there are no positions); events = collisions.
  Sample sample();

  [[nodiscard]] double time() const { return time_; }
  [[nodiscard]] std::uint64_t collisions() const { return collisions_; }
  /// Candidate pairs per unit of physical time now (Λ), an upper bound of the collision rate.
  [[nodiscard]] double candidate_rate() const { return rate_; }
  [[nodiscard]] std::optional<StopReason> stop_reason() const { return stop_reason_; }
  [[nodiscard]] double temperature() const;
  /// Physical velocities, d per particle (for tests).
  [[nodiscard]] std::vector<double> velocities() const;
  /// Candidates drawn so far (collisions / candidates is the acceptance of the majorant).
  [[nodiscard]] std::uint64_t candidates() const { return candidates_; }

 private:
  // One particle's velocity, padded to 32 bytes in 3D so that it never straddles a cache line.
  static constexpr int k_stride = D == 2 ? 2 : 4;
  struct alignas(8 * k_stride) Velocity {
    double u[k_stride] = {};
  };

  void draw_maxwell_velocities(Rng& rng);
  void bookkeeping();
  void update_rate();
  void set_threshold();
  bool collide(std::uint32_t i, std::uint32_t j, const double* g, double g2, Rng& rng);
  struct Pair {
    std::uint32_t i = 0, j = 0;
  };
  /// A uniform distinct pair, its velocities prefetched: candidates do not depend on the state,
  /// so they are drawn k_lookahead candidates ahead and their cache lines arrive while the
  /// current ones are tested.
  Pair draw_pair(Rng& rng);
  static constexpr unsigned k_lookahead = 16;

  std::uint32_t n_ = 0;
  ConstantRestitution rule_;     // the MD's collision rule
  double rate_per_bound_ = 0.0;  // Λ / (2B/s): n g2 β_d (N − 1) / 2
  bool contacts_on_ = false;
  std::uint64_t collision_limit_ = 0;
  double min_temperature_ = 0.0;

  std::vector<Velocity> velocity_;
  Rng rng_;  // candidate pairs, acceptance, waiting times, contact vectors
  Pair ahead_[k_lookahead];
  unsigned next_ahead_ = 0;
  double scale_ = 1.0;        // s: internal velocity u = s v
  double sum_u2_ = 0.0;       // Σ u², updated by every collision, recomputed every N/4
  double bound_ = 0.0;        // B ≥ max |u_i|
  double pair_bound2_ = 0.0;  // (2B)² ≥ |g|² of every pair
  double rate_ = 0.0;         // Λ in physical time
  double clock_ = 0.0;        // physical time at the last flush
  double time_ = 0.0;         // physical time of the state (a stop time reached, or a stop)
  double threshold_ = 0.0;    // Π u_k below this: the stop time is crossed
  double target_ = 0.0;       // the stop time of the current advance_to
  double survival_ = 1.0;     // Π u_k of the candidates since the last flush
  // The candidate whose time passed the last stop time: tested first by the next advance_to.
  bool pending_ = false;
  Pair pending_pair_;
  std::uint64_t pending_uniforms_ = 0;
  double min_sum_u2_ = 0.0;   // min_temperature in internal units of Σ u²
  std::uint64_t collisions_ = 0;
  std::uint64_t candidates_ = 0;
  std::uint64_t next_bookkeeping_ = 0;
  std::optional<StopReason> stop_reason_;  // set when a stop condition fired
  ContactMoments contacts_;
};

/// One DSMC run with the MD run's interface (run.hpp): validates p (std::invalid_argument; tc > 0
/// and snapshot_times are refused, see below), samples on sample_times(p), returns the same
/// RunResult. relax_collisions_per_particle is ignored: the initial Maxwell state already is the
/// elastic gas's stationary state (there is no positional structure to melt). p.method is not
/// read: sim::run calls this for method = dsmc, and tests may call it directly.
RunResult run_dsmc(const Parameters& p, const ProgressCallback& progress = {});

/// The checks that DSMC adds to validate(p) (validate calls it for method = dsmc): randomize =
/// none (the shuffles permute velocities among particles; without positions the state is the
/// multiset of velocities, which a permutation leaves unchanged, so a shuffled run would be the
/// plain one under another name), tc = 0 (the TC model needs per-particle collision histories
/// that this method does not keep) and no snapshot_times (there are no positions).
void validate_dsmc(const Parameters& p);

}  // namespace molchaos::sim
