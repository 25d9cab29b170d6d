// The memory a run will hold, known from its parameters before it starts, against what this
// process may use: a run whose snapshots alone exceed the machine is refused at once, not after
// hours of work by the allocator (or the kernel's out-of-memory killer) with nothing written.
#pragma once

#include <cstdint>
#include <optional>

#include "molchaos/sim/parameters.hpp"

namespace molchaos::sim {

/// Bytes per particle that a run holds at least: the engine's records (the bench's
/// engine_bytes_per_particle, doc/benchmarks.md: 155-220 per disk, 171-311 per sphere, peaks of
/// whole runs above that) or DSMC's one velocity (padded to 32 bytes in 3D: dsmc.hpp), and each
/// snapshot's positions and velocities in doubles.
inline constexpr std::uint64_t k_least_engine_bytes_per_disk = 150;
inline constexpr std::uint64_t k_least_engine_bytes_per_sphere = 170;
inline constexpr std::uint64_t k_dsmc_bytes_per_particle_2d = 16;
inline constexpr std::uint64_t k_dsmc_bytes_per_particle_3d = 32;
std::uint64_t snapshot_bytes_per_particle(int dimension);  // 2d doubles: 32 (d = 2), 48 (d = 3)

struct MemoryNeed {
  std::uint64_t engine = 0;     ///< the method's own data
  std::uint64_t snapshots = 0;  ///< every snapshot time's configuration
  std::uint64_t total() const { return engine + snapshots; }
};

/// The least memory a run of `p` holds (validated parameters).
MemoryNeed least_memory_need(const Parameters& p);

/// The most this process may allocate: the smallest of the machine's memory and swap, the
/// address-space and data limits (ulimit -v, -d) and a cgroup's memory.max; none when none is
/// known.
std::optional<std::uint64_t> memory_limit_bytes();

/// Throws std::invalid_argument naming `snapshot_times` (or `particles`, when the method's own
/// data exceed it) when least_memory_need(p) exceeds `limit`.
void require_memory(const Parameters& p, std::optional<std::uint64_t> limit);

}  // namespace molchaos::sim
