// Progress and failure lines of a sweep.
#include "molchaos/validation/sweep_reporter.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace molchaos::validation {

SweepReporter::SweepReporter(const SweepOptions& options, std::size_t total, int workers)
    : options_(options),
      total_(total),
      workers_(std::max(1, workers)),
      every_(std::max<std::size_t>(1, total / 20)),
      tty_(isatty(STDERR_FILENO) != 0) {}

void SweepReporter::failed(std::size_t i, const sim::Parameters& p, const std::string& what,
                           RunOutcome& out) {
  out.ok = false;
  out.error = fmt::format("run {} (d={}, N={}, n={}, eps={}, randomize={}, seed={}) failed: {}", i,
                          p.dimension, p.particles, p.density, p.restitution,
                          sim::to_string(p.randomize), p.seed, what);
  std::lock_guard<std::mutex> lock(mutex_);
  std::fprintf(stderr, "%s[%s] %s\n", tty_ ? "\n" : "", options_.label.c_str(), out.error.c_str());
}

void SweepReporter::note(const std::string& line) {
  if (!options_.progress) return;
  std::lock_guard<std::mutex> lock(mutex_);
  std::fprintf(stderr, "[%s] %s\n", options_.label.c_str(), line.c_str());
  std::fflush(stderr);
}

void SweepReporter::done(bool from_cache) {
  if (from_cache) ++cached_;
  const std::size_t finished = ++done_;
  if (!options_.progress) return;
  if (!tty_ && finished % every_ != 0 && finished != total_) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::size_t computed = finished - cached_.load();
  const double per_run = computed > 0 ? elapsed / static_cast<double>(computed) : 0.0;
  const double eta = per_run * static_cast<double>(total_ - finished) / workers_;
  // Without a cache (--cache '', bench) no run can come from one: not counted.
  const std::string cached = options_.cache_directory.empty()
                                 ? std::string()
                                 : " (" + std::to_string(cached_.load()) + " from cache)";
  std::lock_guard<std::mutex> lock(mutex_);
  std::fprintf(stderr, "%s[%s] %zu/%zu runs done%s, elapsed %.0f s, ~%.0f s left%s",
               tty_ ? "\r" : "", options_.label.c_str(), finished, total_, cached.c_str(), elapsed,
               eta, tty_ ? (finished == total_ ? "\n" : "") : "\n");
  std::fflush(stderr);
}

}  // namespace molchaos::validation
