// The initial state of a run: non-overlapping positions in the periodic box and Maxwell velocities
// with zero momentum and T = 1. The relaxation that melts it is a run of the engine with the
// elastic collision model (Engine::relax).
#pragma once

#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "molchaos/sim/rng.hpp"

namespace molchaos::sim {

/// The lattice a dense start uses (see place_particles): sites per row, rows (d = 2), and the
/// nearest-site distance; it holds n unit spheres without overlap when that exceeds 1 + 1e-9.
struct StartLattice {
  std::int64_t per_row = 0, rows = 0;
  double nearest = 0;
  bool fits() const { return nearest > 1.0 + 1e-9; }
};
StartLattice start_lattice(int dimension, std::int64_t n, double box);
/// The least density at which place_particles cannot start n particles, every lower one near it
/// starting (the bound near the density of `box`).
double densest_start(int dimension, std::int64_t n, double box);
/// "density X is too high to generate ... reaches n < Y for this N; close packing is Z".
std::string too_dense_message(int dimension, std::int64_t n, double box);

/// Thrown where the build of an initial state finds its interrupt flag set: at millions of
/// particles the build takes seconds (about 2 µs a disk), too long to wait for a Ctrl-C.
struct InitialStateInterrupted : std::runtime_error {
  InitialStateInterrupted() : std::runtime_error("the initial state's build was interrupted") {}
};

/// Throws InitialStateInterrupted when `interrupt` is set, looking at it once in 2^16 steps
/// (`step` counts them): a set flag is seen within milliseconds, at no measurable cost.
inline void stop_build_if_interrupted(const std::atomic<bool>* interrupt, std::int64_t step) {
  if ((step & 0xffff) == 0 && interrupt != nullptr && interrupt->load(std::memory_order_relaxed))
    throw InitialStateInterrupted();
}

/// n non-overlapping unit spheres (pair distances > 1 + 1e-9) in [0, box)^D, particle-major.
/// Random sequential insertion while the packing fraction is low (< 0.25 disks, < 0.2 spheres)
/// and it succeeds; otherwise a lattice with random vacancies and jitter (d = 2: staggered rows,
/// d = 3: simple cubic). Throws std::runtime_error naming the reachable density when even the
/// lattice does not fit, and InitialStateInterrupted when `interrupt` is set.
template <int D>
std::vector<double> place_particles(std::int32_t n, double box, Rng& rng,
                                    const std::atomic<bool>* interrupt = nullptr);

/// D n Maxwell velocity components, particle-major, with zero total momentum and
/// sum v^2 = n D (T = 1) up to rounding.
template <int D>
std::vector<double> maxwell_velocities(std::int32_t n, Rng& rng);

}  // namespace molchaos::sim
