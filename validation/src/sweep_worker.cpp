// One run of a sweep: computed, stored, and a cache write failure kept apart from a failing run.
#include "molchaos/validation/sweep_worker.hpp"

#include <new>
#include <string>

#include "molchaos/sim/run.hpp"

namespace molchaos::validation {

void CacheWriteStop::record(const CacheWriteError& e) {
  const std::lock_guard lock(mutex_);
  if (stopped_) return;
  what_ = e.what();
  stopped_ = true;
}

void CacheWriteStop::throw_if_stopped() const {
  if (!stopped_) return;
  const std::lock_guard lock(mutex_);
  throw CacheWriteError(what_);
}

bool compute_and_store(std::size_t i, const sim::Parameters& p, const SweepOptions& options,
                       SweepReporter& reporter, CacheWriteStop& stop, RunOutcome& out) {
  try {
    out.result = run_and_cache(p, options);
    out.ok = true;
  } catch (const CacheWriteError& e) {
    stop.record(e);
    return false;
  } catch (const std::bad_alloc&) {
    reporter.failed(i, p, std::string(sim::k_out_of_memory_message) + " (or fewer threads)", out);
  } catch (const std::exception& e) {
    reporter.failed(i, p, e.what(), out);
  }
  return true;
}

bool store(const sim::RunResult& result, const SweepOptions& options, CacheWriteStop& stop) {
  try {
    store_cached(result, options);
    return true;
  } catch (const CacheWriteError& e) {
    stop.record(e);
    return false;
  }
}

}  // namespace molchaos::validation
