// Per-collision observers: what a run measures at every collision, chosen at compile time as the
// engine's second template parameter (Engine<D, Observer>), so that a run pays only for what it
// attaches: with NoObserver the hooks are empty inline calls and the compiler removes them.
//
// How to add one: write a default-constructible struct with
//   template <int D> void before(const CollisionView<D>& c);  // pre-collision velocities
//   template <int D> void after(const CollisionView<D>& c, const CollisionOutcome& out);
// (after() sees the velocities after the rule, before any shuffle), read it back through
// engine.observer(), and add the engine's instantiation for it to the list at the end of
// sim/src/engine.cpp. Several observers at once: ObserverPair<A, B> (nest for more). The engine
// resets its observer (to Observer{}) after the relaxation. Observers of the state at sample times
// (temperature series, snapshots, pair correlations) are not collision observers: they read the
// engine between advance_to() calls (sample_observers.hpp) and cost nothing per collision.
#pragma once

#include <cmath>
#include <cstdint>

#include "molchaos/sim/contact_statistics.hpp"
#include "molchaos/sim/result.hpp"

namespace molchaos::sim {

/// One collision as its observers see it. Velocities in the engine's internal units (physical
/// v = u / theta); `vi`, `vj` point at the pair's velocities (before the rule in before(), after
/// it in after()).
template <int D>
struct CollisionView {
  std::int32_t i, j;       // the engine's current particle indices
  const double* e;         // unit vector from j to i at contact
  const double* vi;        // D components
  const double* vj;        // D components
  double normal_velocity;  // (u_i - u_j).e before the rule, < 0
  double temperature;      // internal temperature sum u^2 / (N d) before the rule
  double theta;            // physical v = u / theta
};

/// What the collision did, as the evaluators report it.
struct CollisionOutcome {
  double energy_lost;  // kinetic energy removed by the rule, internal units (m = 1)
  bool made_elastic;   // by the TC model
};

/// Attaches nothing.
struct NoObserver {
  template <int D>
  void before(const CollisionView<D>&) {}
  template <int D>
  void after(const CollisionView<D>&, const CollisionOutcome&) {}
};

/// Contact statistics: the sums of ContactMoments (result.hpp) over the collisions since the last
/// take(), of the pre-collision reduced velocities c = v / sqrt(2T), and the impact-parameter
/// histogram (contact_statistics.hpp).
struct ContactStatistics {
  ContactMoments moments;

  template <int D>
  void before(const CollisionView<D>& c) {
    accumulate<D>(moments, c.vi, c.vj, c.e, c.temperature);
  }
  template <int D>
  void after(const CollisionView<D>&, const CollisionOutcome&) {}

  /// A restored checkpoint's check (Engine::check_restored()).
  bool well_formed() const { return moments.well_formed(); }

  /// The sums since the previous take(); starts the next interval.
  ContactMoments take() {
    const ContactMoments taken = moments;
    moments = {};
    return taken;
  }
};

/// The last collision, in physical units, for tests of the collision rule.
struct CollisionRecord {
  std::int32_t i = -1, j = -1;
  double normal_velocity = 0;                  // (v_i - v_j).e before the collision
  bool made_elastic = false;                   // by the TC model
  double energy_lost = 0;                      // as the collision rule reports it
  double energy_before = 0, energy_after = 0;  // of the pair i, j (before any shuffle)
};

struct LastCollision {
  CollisionRecord record;

  template <int D>
  void before(const CollisionView<D>& c) {
    double sum = 0;
    for (int a = 0; a < D; ++a) sum += c.vi[a] * c.vi[a] + c.vj[a] * c.vj[a];
    record.energy_before = 0.5 * sum / (c.theta * c.theta);
  }
  template <int D>
  void after(const CollisionView<D>& c, const CollisionOutcome& out) {
    double sum = 0;
    for (int a = 0; a < D; ++a) sum += c.vi[a] * c.vi[a] + c.vj[a] * c.vj[a];
    const double inv_theta2 = 1.0 / (c.theta * c.theta);
    record.i = c.i;
    record.j = c.j;
    record.normal_velocity = c.normal_velocity / c.theta;
    record.made_elastic = out.made_elastic;
    record.energy_lost = out.energy_lost * inv_theta2;
    record.energy_after = 0.5 * sum * inv_theta2;
  }
};

/// Two observers at once (nest for more): each hook calls A's, then B's.
template <class A, class B>
struct ObserverPair {
  A first;
  B second;

  template <int D>
  void before(const CollisionView<D>& c) {
    first.before(c);
    second.before(c);
  }
  template <int D>
  void after(const CollisionView<D>& c, const CollisionOutcome& out) {
    first.after(c, out);
    second.after(c, out);
  }
};

}  // namespace molchaos::sim
