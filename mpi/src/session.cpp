// MPI_Init_thread / MPI_Finalize, only under an MPI launcher: a singleton MPI_Init costs about
// half a second on OpenMPI, too much for every `molchaos theory`.
#include "molchaos/mpi/session.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "molchaos/mpi/distributed_sweep.hpp"

namespace molchaos::mpi {

bool launched_by_mpi() {
  if (const char* forced = std::getenv("MOLCHAOS_MPI"); forced && std::strcmp(forced, "0") == 0)
    return false;
  // OpenMPI's mpirun; PMIx (OpenMPI >= 4, srun --mpi=pmix); PMI-1/2 (MPICH hydra, srun --mpi=pmi2).
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

int launched_processes() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* size = std::getenv(name)) return std::max(1, std::atoi(size));
  return 1;
}

int world_rank() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (!initialized || finalized) return 0;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int world_size() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (!initialized || finalized) return 1;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

Session::Session(int& argc, char**& argv) {
  if (!launched_by_mpi()) return;
  // FUNNELED: only the main thread calls MPI; rank 0 computes runs on a second thread.
  int provided = MPI_THREAD_SINGLE;
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    std::fprintf(stderr, "molchaos: MPI_Init_thread failed; running without MPI\n");
    return;
  }
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Session::~Session() {
  if (!active_) return;
  if (rank_ == 0 && size_ > 1) stop_workers();
  MPI_Finalize();
}

int Session::serve() { return serve_sweeps(); }

}  // namespace molchaos::mpi
