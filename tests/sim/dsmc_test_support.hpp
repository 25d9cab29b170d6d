// Shared by the DSMC tests (test_dsmc.cpp, test_dsmc_runs.cpp): the mean of independent runs
// with its standard error, and the parameters of a DSMC gas.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "molchaos/sim/parameters.hpp"

namespace molchaos::sim::testing {

struct MeanError {
  double mean = 0, error = 0;
};

inline MeanError mean_error(const std::vector<double>& x) {
  MeanError m;
  for (double v : x) m.mean += v;
  m.mean /= static_cast<double>(x.size());
  double ss = 0;
  for (double v : x) ss += (v - m.mean) * (v - m.mean);
  const double n = static_cast<double>(x.size());
  m.error = std::sqrt(ss / (n - 1) / n);
  return m;
}

// d = 2 at n = 0.05, d = 3 at packing 0.1; no relaxation (DSMC does none); t_end for the test to
// set.
inline Parameters gas_parameters(int d, std::int64_t particles, double restitution,
                                 std::uint64_t seed) {
  Parameters p;
  p.dimension = d;
  p.particles = particles;
  p.density = d == 2 ? 0.05 : 0.6 / std::numbers::pi;
  p.restitution = restitution;
  p.seed = seed;
  p.t_end = 1e300;
  p.relax_collisions_per_particle = 0;  // DSMC does no relaxation
  return p;
}

}  // namespace molchaos::sim::testing
