// The entry point of the engine: run(Parameters) builds the initial state, relaxes it elastically,
// then runs the cooling gas to t_end and returns the sampled time series.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "molchaos/sim/checkpoint.hpp"

#include "molchaos/sim/parameters.hpp"
#include "molchaos/sim/result.hpp"

namespace molchaos::sim {

using ProgressCallback = std::function<void(double fraction_done)>;

/// What a run that does not fit in memory says (std::bad_alloc), in the CLI and the Python
/// module alike: the engine's own need per particle (doc/benchmarks.md: 159-175 bytes per disk,
/// 171-311 per sphere; a whole run of 10^6 disks peaks at 208), DSMC's (one velocity, padded to
/// 32 bytes in 3D: dsmc.hpp), and the snapshots' (positions and velocities in doubles), which
/// many snapshot times make the larger part.
inline constexpr const char* k_out_of_memory_message =
    "out of memory; an event-driven run holds about 210 bytes per disk and 310 per sphere (DSMC "
    "16 and 32), and each snapshot 32 more per disk and 48 per sphere: ask for fewer particles or "
    "fewer snapshot times";

/// Richer progress report for front ends that show a rate.
struct Progress {
  double fraction_done = 0;
  std::uint64_t collisions = 0;
  std::uint64_t events = 0;
  double wall_seconds = 0;
  bool relaxing = false;  // in the relaxation before t = 0 (fraction_done 0, counts its own)
};
using ProgressReporter = std::function<void(const Progress&)>;

/// Validates p (std::invalid_argument), runs, returns. A run that stops early (collapse,
/// max_collisions, min_temperature) returns normally; stop_reason says why.
RunResult run(const Parameters& p, const ProgressCallback& progress = {});
RunResult run_with_progress(const Parameters& p, const ProgressReporter& progress);
/// The same with checkpoints (checkpoint.hpp): writes them where and when `checkpoints` asks, and
/// starts from checkpoints.restart when it names one (the result is then byte for byte the
/// uninterrupted run's). Returns nothing when *checkpoints.interrupt was set: the checkpoint (if
/// a path is given) holds the run at that point (none when it was set while the initial state was
/// built or relaxed). Throws CheckpointError for a checkpoint that does not fit p.
std::optional<RunResult> run_with_checkpoints(const Parameters& p, const ProgressReporter& progress,
                                              const CheckpointOptions& checkpoints);

/// Log-spaced sample times: 0, t_first * 10^(j / samples_per_decade) < t_end, and t_end.
std::vector<double> sample_times(const Parameters& p);

/// Enskog collision frequency per particle at temperature T: 2 n g2 sqrt(pi T) (d = 2),
/// 4 n g2 sqrt(pi T) (d = 3), with the contact values named in parameters.hpp's conventions.
double enskog_collision_frequency(int dimension, double density, double temperature);
double contact_value_g2(int dimension, double density);

}  // namespace molchaos::sim
