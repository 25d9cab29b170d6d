// Which engine executes sweeps for this process: the local thread pool, or (when built with MPI
// and started under mpirun with more than one rank) the MPI distributor.
#pragma once

#include "molchaos/validation/sweep.hpp"

namespace molchaos::app {

/// Empty runner = local thread pool.
validation::SweepRunner default_sweep_runner();

}  // namespace molchaos::app
