// Which engine executes sweeps for this process: the local thread pool, or (when built with MPI
// and started under mpirun with more than one rank) the MPI distributor.
#pragma once

#include "molchaos/validation/sweep.hpp"

namespace molchaos::app {

/// Empty runner = local thread pool.
validation::SweepRunner default_sweep_runner();

/// Refuses --threads (UsageError) when default_sweep_runner() hands the runs to MPI ranks, one
/// run per rank at a time, where the thread count would be dropped without a word.
void reject_threads_on_ranks(bool threads_given);

}  // namespace molchaos::app
