// Shared by the physics tests: the elastic-limit check. At restitution 1 the gas is in equilibrium;
// the collision frequency per particle, omega = 2 C / (N t), is measured over independent seeds and
// compared with Enskog's (2 n g2 sqrt(pi T) for disks, 4 n g2 sqrt(pi T) for spheres, T = 1).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "molchaos/sim/run.hpp"

namespace molchaos::sim::testing {

struct Ratio {
  double mean = 0, standard_error = 0;  // of omega / omega_Enskog over the seeds
  int seeds = 0;
  std::uint64_t collisions_per_seed = 0;
};

inline Ratio elastic_collision_frequency_ratio(int dimension, double density, Randomization mode,
                                               std::int64_t particles, double t_end, int seeds) {
  std::vector<double> ratios;
  Ratio out;
  for (int s = 1; s <= seeds; ++s) {
    Parameters p;
    p.dimension = dimension;
    p.particles = particles;
    p.density = density;
    p.restitution = 1.0;
    p.randomize = mode;
    p.seed = static_cast<std::uint64_t>(1000 + s);
    p.t_end = t_end;
    p.samples_per_decade = 1;
    p.t_first_sample = t_end;
    const RunResult r = run(p);
    const double omega =
        2.0 * static_cast<double>(r.collisions) / (static_cast<double>(particles) * t_end);
    ratios.push_back(omega / enskog_collision_frequency(dimension, density, 1.0));
    out.collisions_per_seed = r.collisions;
  }
  double sum = 0, sum2 = 0;
  for (double x : ratios) sum += x;
  out.mean = sum / seeds;
  for (double x : ratios) sum2 += (x - out.mean) * (x - out.mean);
  out.standard_error = std::sqrt(sum2 / (seeds - 1) / seeds);
  out.seeds = seeds;
  return out;
}

}  // namespace molchaos::sim::testing
