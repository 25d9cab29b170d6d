// What every sweep runner (the local thread pool, the MPI master) does with one run: compute it,
// store it, and tell a failing run from a failing cache. A run whose result cannot be stored has
// not failed: the sweep stops taking runs and ends with that CacheWriteError, which names the
// cache folder and the OS error, instead of counting runs as failed.
#pragma once

#include <atomic>
#include <cstddef>
#include <mutex>
#include <string>

#include "molchaos/sim/parameters.hpp"
#include "molchaos/sim/result.hpp"
#include "molchaos/validation/sweep.hpp"
#include "molchaos/validation/sweep_reporter.hpp"

namespace molchaos::validation {

/// The first cache write failure of a sweep, shared by its workers. Thread-safe.
class CacheWriteStop {
 public:
  /// Records `e` unless an earlier failure was recorded.
  void record(const CacheWriteError& e);
  /// Whether a failure was recorded: the sweep takes no new runs.
  bool stopped() const { return stopped_; }
  /// Throws the recorded CacheWriteError; does nothing if none was recorded.
  void throw_if_stopped() const;

 private:
  std::atomic<bool> stopped_{false};
  mutable std::mutex mutex_;
  std::string what_;
};

/// Computes run i on this process and stores it in the cache (run_and_cache). A failing run is
/// marked in `out` and reported; either way the run counts as done and true is returned. A cache
/// write failure goes to `stop` and gives false: the run counts neither as done nor as failed.
bool compute_and_store(std::size_t i, const sim::Parameters& p, const SweepOptions& options,
                       SweepReporter& reporter, CacheWriteStop& stop, RunOutcome& out);

/// Stores a result computed elsewhere (an MPI worker's); false, with the failure in `stop`, if the
/// cache cannot take it.
bool store(const sim::RunResult& result, const SweepOptions& options, CacheWriteStop& stop);

}  // namespace molchaos::validation
