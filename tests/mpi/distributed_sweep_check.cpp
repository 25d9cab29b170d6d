// Run under mpirun with K >= 2 ranks: the distributed sweep returns what the local thread pool
// returns (same outcomes, same CSV text, same error texts), writes a byte-identical cache, and a
// second pass resumes everything from that cache. Usage: distributed_sweep_check WORK_DIR
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "molchaos/mpi/distributed_sweep.hpp"
#include "molchaos/mpi/session.hpp"
#include "molchaos/sim/csv.hpp"
#include "molchaos/validation/ensemble.hpp"

using namespace molchaos;
namespace fs = std::filesystem;

namespace {

int failures = 0;

void check(bool condition, const std::string& what) {
  if (condition) return;
  ++failures;
  std::fprintf(stderr, "FAIL: %s\n", what.c_str());
}

std::string csv_text(const sim::RunResult& r) {
  std::ostringstream out;
  sim::write_csv(r, out);
  return out.str();
}

std::map<std::string, std::string> folder_contents(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    files[entry.path().filename().string()] = bytes.str();
  }
  return files;
}

void compare(const std::vector<validation::RunOutcome>& local,
             const std::vector<validation::RunOutcome>& distributed, const std::string& pass) {
  check(local.size() == distributed.size(), pass + ": number of outcomes");
  for (std::size_t i = 0; i < std::min(local.size(), distributed.size()); ++i) {
    const auto& a = local[i];
    const auto& b = distributed[i];
    const std::string run = pass + ": run " + std::to_string(i);
    check(a.ok == b.ok, run + ": ok differs");
    check(a.error == b.error, run + ": error text differs:\n  " + a.error + "\n  " + b.error);
    if (a.ok && b.ok) {
      check(csv_text(a.result) == csv_text(b.result), run + ": result differs");
      check(a.result.snapshots.size() == b.result.snapshots.size(), run + ": snapshots differ");
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  if (session.is_worker()) return session.serve();
  if (!session.active() || session.size() < 2 || argc != 2) {
    std::fprintf(stderr, "usage: mpirun -np K (K >= 2) distributed_sweep_check WORK_DIR\n");
    return 2;
  }
  const fs::path work = argv[1];
  fs::remove_all(work);

  validation::EnsembleSpec spec;
  spec.particles = 400;
  spec.densities = {0.05};
  spec.restitutions = {0.85, 0.95};
  spec.modes = {sim::Randomization::none, sim::Randomization::flux};
  spec.seeds = 3;
  auto runs = validation::expand(spec);
  // A run that fails (restitution out of range): reported with its parameters, sweep goes on.
  auto bad = runs.front();
  bad.restitution = 1.5;
  runs.insert(runs.begin() + 2, bad);
  // A run with snapshots: they do not travel as CSV text, so rank 0 must compute it.
  auto with_snapshot = runs.back();
  with_snapshot.snapshot_times = {0.5};
  runs.push_back(with_snapshot);

  validation::SweepOptions local;
  local.cache_directory = (work / "local").string();
  local.threads = 2;
  local.progress = false;
  local.version = "test";
  validation::SweepOptions distributed = local;
  distributed.cache_directory = (work / "mpi").string();
  distributed.progress = true;
  distributed.label = "mpi check";

  const auto expected = validation::run_sweep(runs, local);
  mpi::DistributionStats stats;
  const auto first = mpi::run_sweep_distributed_with_stats(runs, distributed, &stats);
  for (std::size_t rank = 0; rank < stats.runs_per_rank.size(); ++rank)
    check(stats.runs_per_rank[rank] > 0, "rank " + std::to_string(rank) + " computed no run");
  compare(expected, first, "first pass");
  check(!first[2].ok && first[2].error.find("eps=1.5") != std::string::npos,
        "the failing run names its parameters: " + first[2].error);
  check(first.back().result.snapshots.size() == 1, "the snapshot run kept its snapshot");
  check(folder_contents(work / "local") == folder_contents(work / "mpi"),
        "cache folders differ (file names or bytes)");

  const auto second = mpi::run_sweep_distributed(runs, distributed);
  compare(expected, second, "resumed pass");
  std::size_t from_cache = 0;
  for (const auto& o : second) from_cache += o.from_cache ? 1 : 0;
  // Everything but the failed run and the snapshot run (never cached) comes from the cache.
  check(from_cache == runs.size() - 2, "resumed pass: " + std::to_string(from_cache) + " of " +
                                           std::to_string(runs.size() - 2) + " runs from cache");
  std::fprintf(stderr, "%s: %zu runs on %d ranks\n", failures ? "FAILED" : "ok", runs.size(),
               session.size());
  return failures ? 1 : 0;
}
