// Observers of the state at sample times: the temperature series (T, a2, collision counts and
// the long-wavelength modes that signal the break-down of homogeneous cooling) and snapshots.
// They read the engine between advance_to() calls and cost nothing per collision. A new one
// (e.g. pair correlations) is a function or struct of the same kind: it reads positions with
// engine.position_now(i, r), internal velocities with engine.internal_velocity(i) (physical
// v = u / theta, engine.clock()), and is called by run() at its sample times.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

#include "molchaos/sim/result.hpp"

namespace molchaos::sim {

/// The temperature series' sample of the engine's present state (t, T, a2, counts, modes).
template <class Engine>
Sample temperature_sample(const Engine& engine) {
  constexpr int D = Engine::dimension;
  const std::int32_t n_particles = engine.size();
  const double box = engine.box();
  const double theta = engine.clock().theta;
  Sample s;
  s.t = engine.time();
  double m2 = 0, m4 = 0;
  for (std::int32_t i = 0; i < n_particles; ++i) {
    const double* u = engine.internal_velocity(i);
    double u2 = 0;
    for (int a = 0; a < D; ++a) u2 += u[a] * u[a];
    m2 += u2;
    m4 += u2 * u2;
  }
  const double n = static_cast<double>(n_particles);
  const double t_internal = m2 / (n * D);
  s.temperature = t_internal / (theta * theta);
  s.a2 = m2 > 0 ? static_cast<double>(D) / (D + 2) * (m4 / n) / ((m2 / n) * (m2 / n)) - 1.0 : 0.0;
  s.collisions = engine.collisions();
  s.events = engine.events();

  // Smallest wavevectors k = 2 pi / L along each axis.
  const double k = 2.0 * std::numbers::pi / box;
  double density_sum = 0, velocity_sum = 0;
  for (int axis = 0; axis < D; ++axis) {
    double rho_c = 0, rho_s = 0, j_c[D] = {}, j_s[D] = {};
    for (std::int32_t i = 0; i < n_particles; ++i) {
      double r[D];
      engine.position_now(i, r);
      const double* u = engine.internal_velocity(i);
      const double c = std::cos(k * r[axis]), sn = std::sin(k * r[axis]);
      rho_c += c;
      rho_s += sn;
      for (int a = 0; a < D; ++a) {
        j_c[a] += u[a] * c;
        j_s[a] += u[a] * sn;
      }
    }
    density_sum += (rho_c * rho_c + rho_s * rho_s) / n;
    double j2 = 0;
    for (int a = 0; a < D; ++a) j2 += j_c[a] * j_c[a] + j_s[a] * j_s[a];
    velocity_sum += t_internal > 0 ? j2 / (n * D * t_internal) : 0.0;
  }
  s.density_mode = density_sum / D;
  s.velocity_mode = velocity_sum / D;
  return s;
}

/// Positions (in [0, box)) and physical velocities of the present state, in the particles' original
/// order.
template <class Engine>
Snapshot snapshot_of(const Engine& engine) {
  constexpr int D = Engine::dimension;
  const std::int32_t n_particles = engine.size();
  const double box = engine.box();
  Snapshot snap;
  snap.t = engine.time();
  snap.box = box;
  snap.collisions = engine.collisions();
  snap.positions.resize(static_cast<std::size_t>(n_particles) * D);
  snap.velocities.resize(static_cast<std::size_t>(n_particles) * D);
  for (std::int32_t i = 0; i < n_particles; ++i) {
    double r[D];
    engine.position_now(i, r);
    const double* u = engine.internal_velocity(i);
    const std::size_t id = static_cast<std::size_t>(engine.original_index(i));
    for (int a = 0; a < D; ++a) {
      double x = r[a];
      if (x < 0) x += box;
      if (x >= box) x -= box;
      snap.positions[D * id + a] = x;
      snap.velocities[D * id + a] = engine.clock().physical_velocity(u[a]);
    }
  }
  return snap;
}

}  // namespace molchaos::sim
