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
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/csv.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/validation/sweep_reporter.hpp"
#include "molchaos/validation/sweep_worker.hpp"

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
    if (!sim::omitted(p, info))
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

std::string cache_path(const sim::Parameters& p, const SweepOptions& o) {
  return (std::filesystem::path(o.cache_directory) / (cache_key(p, o.version) + ".csv")).string();
}

namespace {

bool same_parameters(const sim::Parameters& a, const sim::Parameters& b) {
  return canonical_parameters(a, "") == canonical_parameters(b, "");
}

std::string fnv1a64(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return fmt::format("{:016x}", h);
}

// A cache entry is two lines, the key it was stored under and the FNV-1a checksum of the rest,
// then the run's CSV exactly as write_csv writes it. Any change to a byte of the CSV (a digit of
// T, a header, a row dropped with `rows` adjusted) changes the checksum: FNV-1a maps two texts
// differing in one byte to different hashes, and any other change survives only with chance
// 2^-64.
constexpr std::string_view k_key_line = "# cache_key = ";
constexpr std::string_view k_checksum_line = "# checksum = fnv1a64:";

// The CSV text of a verified entry; throws std::runtime_error saying what does not match.
std::string verified_content(const std::string& path, const std::string& key) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto end1 = text.find('\n');
  const auto end2 = end1 == std::string::npos ? end1 : text.find('\n', end1 + 1);
  if (end2 == std::string::npos || text.compare(0, k_key_line.size(), k_key_line) != 0 ||
      text.compare(end1 + 1, k_checksum_line.size(), k_checksum_line) != 0)
    throw std::runtime_error("no cache_key/checksum header");
  const std::string stored_key = text.substr(k_key_line.size(), end1 - k_key_line.size());
  if (stored_key != key)
    throw std::runtime_error("stored under key " + stored_key + ", expected " + key);
  const auto start = end1 + 1 + k_checksum_line.size();
  const std::string stored_sum = text.substr(start, end2 - start);
  std::string content = text.substr(end2 + 1);
  if (fnv1a64(content) != stored_sum)
    throw std::runtime_error("checksum mismatch (content changed since it was stored)");
  return content;
}

}  // namespace

bool load_cached(const sim::Parameters& p, const SweepOptions& o, sim::RunResult& out) {
  if (o.cache_directory.empty()) return false;
  const std::string path = cache_path(p, o);
  // A folder that cannot be searched hides its entries: recompute (storing then names the folder).
  std::error_code unreadable;
  if (!std::filesystem::exists(path, unreadable)) return false;
  // Snapshots are not stored in the run file; a run that asked for them is recomputed.
  if (!p.snapshot_times.empty()) return false;
  try {
    std::istringstream content(verified_content(path, cache_key(p, o.version)));
    sim::RunResult r = sim::read_csv(content);
    if (!same_parameters(r.parameters, p))
      throw std::runtime_error("holds other parameters than its key says");
    out = std::move(r);
    return true;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "[%s] warning: cache entry %s is corrupt (%s); recomputing\n",
                 o.label.c_str(), path.c_str(), e.what());
    return false;
  }
}

void store_cached(const sim::RunResult& r, const SweepOptions& o) {
  if (o.cache_directory.empty()) return;
  std::ostringstream csv;
  sim::write_csv(r, csv);
  const std::string content = csv.str();
  try {
    std::filesystem::create_directories(o.cache_directory);
    sim::write_file_atomically(cache_path(r.parameters, o), [&](std::ostream& out) {
      out << k_key_line << cache_key(r.parameters, o.version) << '\n'
          << k_checksum_line << fnv1a64(content) << '\n'
          << content;
    });
  } catch (const std::exception& e) {
    throw CacheWriteError("cannot store a run in the cache " + o.cache_directory + ": " + e.what());
  }
}

sim::RunResult run_and_cache(const sim::Parameters& p, const SweepOptions& o) {
  sim::RunResult r = sim::run(p);
  if (r.stop_reason == sim::StopReason::collapse)
    throw std::runtime_error("run stopped: " + sim::stop_message(r));
  store_cached(r, o);
  return r;
}

void remove_stale_temporaries(const std::string& cache_directory) {
  sim::remove_stale_temporaries(cache_directory);
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
  CacheWriteStop stop;
  auto worker = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= runs.size() || stop.stopped()) return;
      RunOutcome& outcome = out[i];
      outcome.ok = outcome.from_cache = load_cached(runs[i], o, outcome.result);
      if (!outcome.from_cache && !compute_and_store(i, runs[i], o, reporter, stop, outcome)) return;
      reporter.done(outcome.from_cache);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  stop.throw_if_stopped();
  return out;
}

}  // namespace molchaos::validation
