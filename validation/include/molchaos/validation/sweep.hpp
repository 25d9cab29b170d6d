// Ensembles and parameter sweeps: independent runs executed in parallel on the local cores,
// cached on disk by parameters and code version, resumable after an interruption.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "molchaos/sim/parameters.hpp"
#include "molchaos/sim/result.hpp"

namespace molchaos::validation {

/// Seed of run `index` of an ensemble: a SplitMix64 hash of (base seed, index). Never derived
/// from a thread, rank or clock, so a run's result does not depend on who ran it.
std::uint64_t derive_seed(std::uint64_t base_seed, std::uint64_t index);

/// Canonical text of the code version and every parameter of the table, "name=value;" with
/// values as the CSV header prints them (shortest round-trip decimals); a row added later is left
/// out at its default (ParameterInfo::omitted_at_default), so older entries keep their keys.
std::string canonical_parameters(const sim::Parameters& p, const std::string& version);

/// Cache file name: 16 hex digits of a 64-bit FNV-1a hash of canonical_parameters().
std::string cache_key(const sim::Parameters& p, const std::string& version);

struct SweepOptions;
struct RunOutcome;
/// Executes a whole sweep somewhere else (e.g. over MPI ranks); must return exactly what the
/// local run_sweep would, in input order.
using SweepRunner = std::function<std::vector<RunOutcome>(const std::vector<sim::Parameters>&,
                                                          const SweepOptions&)>;

struct SweepOptions {
  std::string cache_directory;  ///< empty: no cache
  int threads = 0;              ///< 0: std::thread::hardware_concurrency()
  bool progress = true;         ///< runs done / total, elapsed, estimated time left on stderr
  std::string label = "sweep";
  std::string version;  ///< code version for the cache key (molchaos::k_version)
  SweepRunner runner;   ///< empty: the local thread pool
};

struct RunOutcome {
  sim::RunResult result;
  bool ok = false;
  bool from_cache = false;
  std::string error;  ///< what went wrong, with the run's parameters
};

/// Runs every parameter set (dynamic load balance: each worker takes the next undone run).
/// A failing run is reported in its outcome and on stderr; the others go on. Results come back
/// in input order. Cache entries that are missing, unreadable, corrupt or for other parameters
/// are recomputed; every file is written to a temporary name and renamed.
std::vector<RunOutcome> run_sweep(const std::vector<sim::Parameters>& runs,
                                  const SweepOptions& options);

/// Deletes this suite's temporary files of writers that no longer exist (a sweep killed
/// mid-write); see sim::remove_stale_temporaries for the pattern and the age rule.
void remove_stale_temporaries(const std::string& cache_directory);

/// The local thread pool behind run_sweep (run_sweep delegates to options.runner when set).
std::vector<RunOutcome> run_sweep_locally(const std::vector<sim::Parameters>& runs,
                                          const SweepOptions& options);

/// Loads a cached run if a valid entry exists (used by run_sweep and by the MPI driver). Never
/// throws: an entry it cannot find, read or verify is to be recomputed (false).
bool load_cached(const sim::Parameters& p, const SweepOptions& options, sim::RunResult& out);
/// The one place a run's cache file lives: <cache_directory>/<cache_key>.csv.
std::string cache_path(const sim::Parameters& p, const SweepOptions& options);
/// A cache entry could not be written (a full disk, a folder gone): a failure of the sweep's
/// storage, not of the run. The message names the cache folder and the reason; every sweep
/// runner stops at it instead of counting the run as failed (see sweep_worker.hpp).
struct CacheWriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
/// Stores a run under its key with a checksum of its content (atomically); no-op without cache.
/// load_cached reports an entry whose key or checksum does not match and recomputes it. Throws
/// CacheWriteError.
void store_cached(const sim::RunResult& result, const SweepOptions& options);
/// Runs one parameter set and stores it in the cache; throws on failure.
sim::RunResult run_and_cache(const sim::Parameters& p, const SweepOptions& options);

}  // namespace molchaos::validation
