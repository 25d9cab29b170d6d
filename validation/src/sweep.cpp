// Local parallel sweep with an on-disk cache.
#include "molchaos/validation/sweep.hpp"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <sstream>
#include <thread>

#include "molchaos/sim/csv.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/validation/sweep_reporter.hpp"

namespace molchaos::validation {

std::uint64_t derive_seed(std::uint64_t base_seed, std::uint64_t index) {
  std::uint64_t z = base_seed + 0x9E3779B97F4A7C15ULL * (index + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

std::string canonical_parameters(const sim::Parameters& p, const std::string& version) {
  std::string s = "version=" + version + ";";
  for (const sim::ParameterInfo& info : sim::parameter_table())
    s += std::string(info.name) + "=" + sim::format_value(p, info) + ";";
  return s;
}

std::string cache_key(const sim::Parameters& p, const std::string& version) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : canonical_parameters(p, version)) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return fmt::format("{:016x}", h);
}

namespace {

std::string cache_path(const sim::Parameters& p, const SweepOptions& o) {
  return (std::filesystem::path(o.cache_directory) / (cache_key(p, o.version) + ".csv")).string();
}

bool same_parameters(const sim::Parameters& a, const sim::Parameters& b) {
  return canonical_parameters(a, "") == canonical_parameters(b, "");
}

}  // namespace

bool load_cached(const sim::Parameters& p, const SweepOptions& o, sim::RunResult& out) {
  if (o.cache_directory.empty()) return false;
  const std::string path = cache_path(p, o);
  if (!std::filesystem::exists(path)) return false;
  try {
    sim::RunResult r = sim::read_csv_file(path);
    // Snapshots are not stored in the run file; a run that asked for them is recomputed.
    // The version is part of the key; the parameters are compared to rule out a hash collision.
    if (!same_parameters(r.parameters, p) || !p.snapshot_times.empty()) return false;
    out = std::move(r);
    return true;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "[%s] cache entry %s is corrupt (%s); recomputing\n", o.label.c_str(),
                 path.c_str(), e.what());
    return false;
  }
}

sim::RunResult run_and_cache(const sim::Parameters& p, const SweepOptions& o) {
  sim::RunResult r = sim::run(p);
  if (r.stop_reason.rfind("collapse", 0) == 0)
    throw std::runtime_error("run stopped: " + r.stop_reason);
  if (!o.cache_directory.empty()) {
    std::filesystem::create_directories(o.cache_directory);
    sim::write_csv_file(r, cache_path(p, o));
  }
  return r;
}

void remove_stale_temporaries(const std::string& cache_directory) {
  if (cache_directory.empty() || !std::filesystem::is_directory(cache_directory)) return;
  for (const auto& entry : std::filesystem::directory_iterator(cache_directory)) {
    // "<key>.csv.tmp.<pid>": left behind only if the writing process was killed mid-write.
    const std::string name = entry.path().filename().string();
    const auto pos = name.find(".tmp.");
    if (pos == std::string::npos) continue;
    const long pid = std::strtol(name.c_str() + pos + 5, nullptr, 10);
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) == 0) continue;  // writer still alive
    std::error_code ec;
    std::filesystem::remove(entry.path(), ec);
  }
}

std::vector<RunOutcome> run_sweep(const std::vector<sim::Parameters>& runs, const SweepOptions& o) {
  remove_stale_temporaries(o.cache_directory);
  return o.runner ? o.runner(runs, o) : run_sweep_locally(runs, o);
}

std::vector<RunOutcome> run_sweep_locally(const std::vector<sim::Parameters>& runs,
                                          const SweepOptions& o) {
  std::vector<RunOutcome> out(runs.size());
  const int threads = o.threads > 0 ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  std::atomic<std::size_t> next{0};
  SweepReporter reporter(o, runs.size(), threads);
  auto worker = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= runs.size()) return;
      RunOutcome& outcome = out[i];
      try {
        outcome.from_cache = load_cached(runs[i], o, outcome.result);
        if (!outcome.from_cache) outcome.result = run_and_cache(runs[i], o);
        outcome.ok = true;
      } catch (const std::exception& e) {
        reporter.failed(i, runs[i], e.what(), outcome);
      }
      reporter.done(outcome.from_cache);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  return out;
}

}  // namespace molchaos::validation
