// Memory a run holds, and what this process may use (see the header).
#include "molchaos/sim/memory_need.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/sysinfo.h>
#endif

namespace molchaos::sim {

std::uint64_t snapshot_bytes_per_particle(int dimension) {
  return 2 * static_cast<std::uint64_t>(dimension) * sizeof(double);
}

namespace {

std::uint64_t least_method_bytes_per_particle(const Parameters& p) {
  const bool disks = p.dimension == 2;
  if (p.method == Method::dsmc)
    return disks ? k_dsmc_bytes_per_particle_2d : k_dsmc_bytes_per_particle_3d;
  return disks ? k_least_engine_bytes_per_disk : k_least_engine_bytes_per_sphere;
}

}  // namespace

MemoryNeed least_memory_need(const Parameters& p) {
  const auto n = static_cast<std::uint64_t>(p.particles);
  return {n * least_method_bytes_per_particle(p),
          n * p.snapshot_times.size() * snapshot_bytes_per_particle(p.dimension)};
}

namespace {

std::string gigabytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GB", static_cast<double>(bytes) / 1e9);
  return text;
}

#if defined(__linux__)
// A cgroup v2 limit ("max" when there is none).
std::optional<std::uint64_t> cgroup_limit() {
  std::ifstream in("/sys/fs/cgroup/memory.max");
  std::string text;
  if (!(in >> text) || text == "max") return std::nullopt;
  try {
    return std::stoull(text);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}
#endif

}  // namespace

std::optional<std::uint64_t> memory_limit_bytes() {
  std::optional<std::uint64_t> limit;
#if defined(__linux__)
  const auto lower = [&limit](std::uint64_t bytes) {
    limit = limit ? std::min(*limit, bytes) : bytes;
  };
  if (struct sysinfo info{}; sysinfo(&info) == 0)
    lower((static_cast<std::uint64_t>(info.totalram) + info.totalswap) * info.mem_unit);
  for (int resource : {RLIMIT_AS, RLIMIT_DATA})
    if (rlimit r{}; getrlimit(resource, &r) == 0 && r.rlim_cur != RLIM_INFINITY) lower(r.rlim_cur);
  if (const auto cgroup = cgroup_limit()) lower(*cgroup);
#endif
  return limit;
}

void require_memory(const Parameters& p, std::optional<std::uint64_t> limit) {
  const MemoryNeed need = least_memory_need(p);
  if (!limit || need.total() <= *limit) return;
  const std::string particles =
      std::to_string(p.particles) + (p.dimension == 2 ? " disks" : " spheres");
  const std::string may_use = "more than this process may use (" + gigabytes(*limit) +
                              ": the machine's memory and swap, ulimit -v and -d, the cgroup's "
                              "memory.max)";
  if (need.engine > *limit)
    throw std::invalid_argument("particles: a run of " + particles + " holds at least " +
                                gigabytes(need.engine) + ", " + may_use + "; allowed: at most " +
                                std::to_string(*limit / least_method_bytes_per_particle(p)) +
                                " particles");
  const std::uint64_t per_snapshot =
      static_cast<std::uint64_t>(p.particles) * snapshot_bytes_per_particle(p.dimension);
  throw std::invalid_argument("snapshot_times: " + std::to_string(p.snapshot_times.size()) +
                              " snapshots of " + particles + " take at least " +
                              gigabytes(need.snapshots) + " beside the run's own " +
                              gigabytes(need.engine) + ", " + may_use + "; allowed: at most " +
                              std::to_string((*limit - need.engine) / per_snapshot) +
                              " snapshot times at this number of particles");
}

}  // namespace molchaos::sim
