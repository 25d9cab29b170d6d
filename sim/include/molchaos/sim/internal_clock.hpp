// The engine's internal units of time and velocity. A cooling gas slows down by many decades; the
// engine keeps its velocities u of order 1 by rescaling them (u -> f u) and keeps event times of
// order 1 by restarting its clock, while the physical time stays exact:
//   physical t = t_offset + theta * tau,   physical v = u / theta.
#pragma once

namespace molchaos::sim {

struct InternalClock {
  double now = 0;       // tau: the internal time of the present
  double t_offset = 0;  // physical time at tau = 0
  double theta = 1;     // physical time per unit of tau

  /// Physical time of the present.
  double time() const { return t_offset + theta * now; }
  /// Internal time of the physical time t.
  double internal_time(double t) const { return (t - t_offset) / theta; }
  /// Physical velocity (or time interval) of an internal one: v = u / theta, dt = theta dtau.
  double physical_velocity(double u) const { return u / theta; }
  double physical_interval(double dtau) const { return dtau * theta; }

  /// The internal time tau (before restart()) on the restarted clock with velocities scaled by
  /// factor: (tau - now) / factor.
  double restarted(double tau, double factor) const { return (tau - now) / factor; }
  /// Restarts the clock at tau = 0 with velocities scaled by factor (u -> factor u): the physical
  /// time is unchanged, theta -> factor theta.
  void restart(double factor) {
    t_offset += theta * now;
    theta *= factor;
    now = 0;
  }
};

}  // namespace molchaos::sim
