// The MPI lifetime of one molchaos process: initialised only when an MPI launcher started it
// (a plain `build/molchaos ...` pays nothing), finalised on scope exit after rank 0 has released
// the worker ranks.
#pragma once

namespace molchaos::mpi {

/// True when an MPI launcher (mpirun/mpiexec of OpenMPI or MPICH, srun with PMI or PMIx) started
/// this process, judged by the variables those launchers set. MOLCHAOS_MPI=0 forces false.
bool launched_by_mpi();

/// The number of processes the launcher started (OMPI_COMM_WORLD_SIZE, PMI_SIZE), read without
/// MPI and whatever MOLCHAOS_MPI says; 1 when no launcher names one.
int launched_processes();

/// Rank and size of MPI_COMM_WORLD; 0 and 1 when MPI is not initialised.
int world_rank();
int world_size();

/// RAII guard for MPI_Init_thread / MPI_Finalize. Rank 0 runs the command; every other rank
/// calls serve() and executes runs that rank 0 hands out until rank 0 says stop. The destructor
/// on rank 0 sends that stop (also on usage errors and other early returns), so workers never hang.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  bool active() const { return active_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  /// A non-root rank of a job with more than one rank: it serves, it does not parse the CLI.
  bool is_worker() const { return active_ && rank_ != 0; }

  /// Worker loop (serve_sweeps in distributed_sweep.hpp); returns the process exit status.
  int serve();

 private:
  bool active_ = false;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace molchaos::mpi
