// The engine benchmark's cases, shared by bench_engine (wall-clock rates) and engine_counts
// (callgrind work counts), so that both measure the same runs.
#pragma once

#include <numbers>

#include "molchaos/sim/parameters.hpp"

namespace molchaos::bench {

/// The paper's run (Fig. 3): d = 2, N = 5000, n = 0.05, restitution 0.93, the given shuffle.
inline sim::Parameters paper_case(sim::Randomization shuffle) {
  sim::Parameters p;
  p.dimension = 2;
  p.particles = 5000;
  p.density = 0.05;
  p.restitution = 0.93;
  p.randomize = shuffle;
  p.relax_collisions_per_particle = 1;
  return p;
}

/// Disks at the paper's kind of state for the size study (bm_disks): d = 2, N particles, density n,
/// restitution 0.9, no shuffle.
inline sim::Parameters disks_case(long particles, double density) {
  sim::Parameters p;
  p.dimension = 2;
  p.particles = particles;
  p.density = density;
  p.restitution = 0.9;
  p.relax_collisions_per_particle = 1;
  return p;
}

/// Elastic hard spheres, N = 1e5, at the given packing fraction (Smallenburg's timed work).
inline sim::Parameters spheres_case(double packing_fraction) {
  sim::Parameters p;
  p.dimension = 3;
  p.particles = 100000;
  p.density = packing_fraction * 6.0 / std::numbers::pi;
  p.restitution = 1.0;
  p.relax_collisions_per_particle = 2;
  return p;
}

}  // namespace molchaos::bench
