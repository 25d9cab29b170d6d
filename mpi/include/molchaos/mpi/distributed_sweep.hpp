// Sweeps over MPI ranks. Rank 0 is the master: it loads cached runs, hands every other run out
// one at a time to whichever rank is free (runs differ in cost by orders of magnitude), computes
// runs itself on a second thread, and writes every cache file. Workers only compute and send back
// the run's CSV text, which round-trips losslessly, so results are bit-identical whatever the
// number of ranks and whichever rank ran them (seeds live in the parameters, never in the rank).
#pragma once

#include <cstddef>
#include <vector>

#include "molchaos/validation/sweep.hpp"

namespace molchaos::mpi {

/// Master side, rank 0 only; a validation::SweepRunner. Same contract as run_sweep: outcomes in
/// input order, failures reported in their outcome and on stderr, cache read and written by this
/// rank as the local runner does; a cache that cannot take a result stops the sweep with that
/// validation::CacheWriteError once the runs in flight are back, as the local runner does.
/// One run per rank at a time: options.threads is not used.
/// Runs that ask for snapshots (not carried by the CSV text) are computed on rank 0.
std::vector<validation::RunOutcome> run_sweep_distributed(const std::vector<sim::Parameters>& runs,
                                                          const validation::SweepOptions& options);

/// Who computed how much (cached runs not counted); for tests and the progress line.
struct DistributionStats {
  std::vector<std::size_t> runs_per_rank;
};
std::vector<validation::RunOutcome> run_sweep_distributed_with_stats(
    const std::vector<sim::Parameters>& runs, const validation::SweepOptions& options,
    DistributionStats* stats);

/// Worker side, ranks 1..K-1: executes jobs until rank 0 sends stop, then returns 0. Prints
/// nothing; a failing run goes back to rank 0 as its error text. A malformed message aborts the
/// whole job (MPI_Abort); a rank that dies is the launcher's business (mpirun ends the job).
int serve_sweeps();

/// Rank 0: tells every worker to leave serve_sweeps(). Called once, when no sweep is running.
void stop_workers();

}  // namespace molchaos::mpi
