// The stderr lines of a sweep, shared by the local thread pool and the MPI distributor: failures
// with their parameters, notes, and "i/total runs done (k from cache), elapsed, ~left" (every line
// on a pipe, about 20 updates in all; one updating line on a terminal). Thread-safe.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

#include "molchaos/sim/parameters.hpp"
#include "molchaos/validation/sweep.hpp"

namespace molchaos::validation {

class SweepReporter {
 public:
  /// `workers`: runs computed at once (threads or ranks), for the time-left estimate.
  SweepReporter(const SweepOptions& options, std::size_t total, int workers);

  /// Marks run i failed: fills out.ok/out.error (with the run's parameters) and prints it.
  void failed(std::size_t i, const sim::Parameters& p, const std::string& what, RunOutcome& out);
  /// A free-form progress line (only when progress is on).
  void note(const std::string& line);
  /// One more run finished (from the cache or computed).
  void done(bool from_cache);

 private:
  const SweepOptions& options_;
  std::size_t total_;
  int workers_;
  std::size_t every_;
  bool tty_;
  std::atomic<std::size_t> done_{0}, cached_{0};
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace molchaos::validation
