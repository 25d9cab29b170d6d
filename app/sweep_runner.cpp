// Sweeps run on the local thread pool, or, when built with MPI and started by mpirun/srun with
// more than one rank, on every rank of the job (rank 0 distributes, see molchaos/mpi/).
#include "sweep_runner.hpp"

#include "cli_support.hpp"

#ifdef MOLCHAOS_HAVE_MPI
#include "molchaos/mpi/distributed_sweep.hpp"
#include "molchaos/mpi/session.hpp"
#endif

namespace molchaos::app {

namespace {
bool sweeps_run_on_ranks() {
#ifdef MOLCHAOS_HAVE_MPI
  return mpi::world_size() > 1;
#else
  return false;
#endif
}
}  // namespace

validation::SweepRunner default_sweep_runner() {
#ifdef MOLCHAOS_HAVE_MPI
  if (sweeps_run_on_ranks()) return mpi::run_sweep_distributed;
#endif
  return {};
}

void reject_threads_on_ranks(bool threads_given) {
  if (threads_given && sweeps_run_on_ranks())
    throw UsageError("--threads",
                     "does not apply under mpirun with more than one rank (each rank computes one "
                     "run at a time, so the ranks are the parallelism): leave it out");
}

}  // namespace molchaos::app
