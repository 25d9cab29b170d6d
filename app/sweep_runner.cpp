// Sweeps run on the local thread pool, or, when built with MPI and started by mpirun/srun with
// more than one rank, on every rank of the job (rank 0 distributes, see molchaos/mpi/).
#include "sweep_runner.hpp"

#ifdef MOLCHAOS_HAVE_MPI
#include "molchaos/mpi/distributed_sweep.hpp"
#include "molchaos/mpi/session.hpp"
#endif

namespace molchaos::app {

validation::SweepRunner default_sweep_runner() {
#ifdef MOLCHAOS_HAVE_MPI
  if (mpi::world_size() > 1) return mpi::run_sweep_distributed;
#endif
  return {};
}

}  // namespace molchaos::app
