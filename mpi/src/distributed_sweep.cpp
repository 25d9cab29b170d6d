// Master–worker sweep over MPI ranks. All MPI calls happen on the main thread of each rank
// (MPI_THREAD_FUNNELED); rank 0's second thread only computes runs.
#include "molchaos/mpi/distributed_sweep.hpp"

#include <fmt/format.h>
#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <climits>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "molchaos/mpi/session.hpp"
#include "molchaos/mpi/wire.hpp"
#include "molchaos/sim/csv.hpp"
#include "molchaos/validation/sweep_reporter.hpp"
#include "molchaos/validation/sweep_worker.hpp"

namespace molchaos::mpi {
namespace {

using validation::RunOutcome;
using validation::SweepOptions;

constexpr int tag(Tag t) { return static_cast<int>(t); }

[[noreturn]] void abort_job(const std::string& what) {
  std::fprintf(stderr, "molchaos: rank %d: %s; aborting the MPI job\n", world_rank(), what.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::abort();  // MPI_Abort does not return; this keeps [[noreturn]] honest.
}

void send(const std::string& bytes, int destination, Tag t) {
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) abort_job("message larger than 2 GB");
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, destination, tag(t),
           MPI_COMM_WORLD);
}

std::string receive(const MPI_Status& probed) {
  int count = 0;
  MPI_Get_count(&probed, MPI_CHAR, &count);
  std::string bytes(static_cast<std::size_t>(count), '\0');
  MPI_Recv(bytes.data(), count, MPI_CHAR, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return bytes;
}

// Waiting by MPI_Iprobe and short sleeps instead of a blocking receive: OpenMPI's blocking
// receive spins a core, and with one rank per core that spin would steal time from the runs.
class Backoff {
 public:
  explicit Backoff(std::chrono::microseconds longest) : longest_(longest) {}
  void sleep() {
    std::this_thread::sleep_for(current_);
    current_ = std::min(current_ * 2, longest_);
  }
  void reset() { current_ = k_shortest; }

 private:
  static constexpr std::chrono::microseconds k_shortest{100};
  std::chrono::microseconds longest_;
  std::chrono::microseconds current_ = k_shortest;
};

// Runs not yet started. Rank 0's compute thread takes the runs only it may do first (those with
// snapshots, which the CSV text does not carry), then competes with the workers for the rest.
class WorkQueue {
 public:
  void add(std::size_t i, bool rank0_only) { (rank0_only ? rank0_only_ : shared_).push_back(i); }
  std::optional<std::size_t> take_remote() { return take(shared_); }
  std::optional<std::size_t> take_local() {
    if (auto i = take(rank0_only_)) return i;
    return take(shared_);
  }

 private:
  std::optional<std::size_t> take(std::deque<std::size_t>& from) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (from.empty()) return std::nullopt;
    const std::size_t i = from.front();
    from.pop_front();
    return i;
  }
  std::mutex mutex_;
  std::deque<std::size_t> shared_, rank0_only_;
};

}  // namespace

std::vector<RunOutcome> run_sweep_distributed(const std::vector<sim::Parameters>& runs,
                                              const SweepOptions& o) {
  return run_sweep_distributed_with_stats(runs, o, nullptr);
}

std::vector<RunOutcome> run_sweep_distributed_with_stats(const std::vector<sim::Parameters>& runs,
                                                         const SweepOptions& o,
                                                         DistributionStats* stats) {
  const std::size_t total = runs.size();
  const int ranks = world_size();
  if (stats) stats->runs_per_rank.assign(static_cast<std::size_t>(ranks), 0);
  std::vector<RunOutcome> out(total);
  if (total == 0) return out;
  validation::SweepReporter reporter(o, total, ranks);

  // Resume: rank 0 alone reads the cache, and only uncached runs travel.
  WorkQueue queue;
  std::size_t to_compute = 0;
  for (std::size_t i = 0; i < total; ++i) {
    if (validation::load_cached(runs[i], o, out[i].result)) {
      out[i].ok = out[i].from_cache = true;
      reporter.done(true);
    } else {
      queue.add(i, !runs[i].snapshot_times.empty());
      ++to_compute;
    }
  }
  if (to_compute == 0) return out;
  reporter.note(fmt::format("{} of {} runs to compute on {} MPI ranks", to_compute, total, ranks));

  // A result the cache cannot take stops the sweep as on the local thread pool: no new runs go
  // out, the runs in flight are received (and dropped), then the CacheWriteError is thrown.
  validation::CacheWriteStop stop;
  std::vector<std::size_t> computed_by(static_cast<std::size_t>(ranks), 0);
  auto compute_here = [&](std::size_t i) {
    if (!validation::compute_and_store(i, runs[i], o, reporter, stop, out[i])) return;
    ++computed_by[0];
    reporter.done(false);
  };
  auto compute_local_share = [&] {
    for (std::optional<std::size_t> i; !stop.stopped() && (i = queue.take_local());)
      compute_here(*i);
  };
  // Rank 0 computes too (with 2 ranks on 2 cores an idle master would waste half the machine),
  // on a second thread, which FUNNELED allows as long as that thread makes no MPI call.
  int thread_level = MPI_THREAD_SINGLE;
  MPI_Query_thread(&thread_level);
  const bool compute_thread = thread_level >= MPI_THREAD_FUNNELED;
  std::thread local;
  if (compute_thread) local = std::thread(compute_local_share);

  auto handle_result = [&](const std::string& bytes, int source) {
    ResultMessage m;
    try {
      m = decode_result(bytes);
    } catch (const std::exception& e) {
      abort_job(fmt::format("bad result message from rank {}: {}", source, e.what()));
    }
    if (m.index >= total)
      abort_job(fmt::format("rank {} returned unknown run {}", source, m.index));
    const auto i = static_cast<std::size_t>(m.index);
    if (stop.stopped()) return;
    ++computed_by[static_cast<std::size_t>(source)];
    sim::RunResult r;
    try {
      if (!m.ok) throw std::runtime_error(m.text);
      std::istringstream text(m.text);
      r = sim::read_csv(text);
      if (validation::canonical_parameters(r.parameters, "") !=
          validation::canonical_parameters(runs[i], ""))
        throw std::runtime_error(
            fmt::format("rank {} ran other parameters than were sent", source));
    } catch (const std::exception& e) {
      reporter.failed(i, runs[i], e.what(), out[i]);
      reporter.done(false);
      return;
    }
    if (!validation::store(r, o, stop)) return;
    out[i].result = std::move(r);
    out[i].ok = true;
    reporter.done(false);
  };

  // Dispatcher: every free worker gets the next run; a result frees its worker again.
  std::size_t in_flight = 0;
  auto feed = [&](int worker) {
    if (stop.stopped()) return;
    if (auto i = queue.take_remote()) {
      send(encode(JobMessage{*i, runs[*i]}), worker, Tag::job);
      ++in_flight;
    }
  };
  for (int worker = 1; worker < ranks; ++worker) feed(worker);
  Backoff backoff(std::chrono::milliseconds(5));
  while (in_flight > 0) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, tag(Tag::result), MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) {
      backoff.sleep();
      continue;
    }
    backoff.reset();
    const std::string bytes = receive(status);
    --in_flight;
    handle_result(bytes, status.MPI_SOURCE);
    feed(status.MPI_SOURCE);
  }
  if (compute_thread)
    local.join();
  else
    compute_local_share();
  stop.throw_if_stopped();

  std::string per_rank;
  for (std::size_t n : computed_by) per_rank += fmt::format(" {}", n);
  reporter.note("runs computed per rank:" + per_rank);
  if (stats) stats->runs_per_rank = computed_by;
  return out;
}

int serve_sweeps() {
  Backoff backoff(std::chrono::milliseconds(20));
  for (;;) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) {
      backoff.sleep();
      continue;
    }
    backoff.reset();
    const std::string bytes = receive(status);
    if (status.MPI_TAG == tag(Tag::stop)) return 0;
    if (status.MPI_TAG != tag(Tag::job))
      abort_job(fmt::format("unexpected message tag {} from rank 0", status.MPI_TAG));
    JobMessage job;
    try {
      job = decode_job(bytes);
    } catch (const std::exception& e) {
      abort_job(fmt::format("bad job message: {}", e.what()));
    }
    // The run itself, exactly as the local runner does it (collapse counts as failure); no
    // cache here: rank 0 writes every file.
    ResultMessage result{job.index, false, {}};
    try {
      const sim::RunResult r = validation::run_and_cache(job.parameters, SweepOptions{});
      std::ostringstream text;
      sim::write_csv(r, text);
      result.text = text.str();
      result.ok = true;
    } catch (const std::exception& e) {
      result.text = e.what();
    }
    send(encode(result), 0, Tag::result);
  }
}

void stop_workers() {
  for (int worker = 1; worker < world_size(); ++worker)
    MPI_Send(nullptr, 0, MPI_CHAR, worker, tag(Tag::stop), MPI_COMM_WORLD);
}

}  // namespace molchaos::mpi
