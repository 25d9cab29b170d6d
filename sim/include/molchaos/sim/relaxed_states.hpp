// Relaxed initial states shared by the runs of one process. An ensemble relaxes the same
// (N, density, seed) once per restitution and per shuffle, yet the relaxation (an elastic run of
// relax_collisions_per_particle, engine.hpp's relax()) depends on neither: the first run keeps its
// engine's state after relaxing, and the next runs of the same key restore it bit for bit (the
// checkpoint's exactness, engine_checkpoint.cpp) instead of relaxing again. A run restored this way
// continues exactly as if it had relaxed itself: same samples, same bytes.
//
// Bounded: a state larger than k_largest_kept_state is not kept (a large single run pays no copy),
// and the oldest states go when the kept ones exceed k_kept_bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "molchaos/sim/parameters.hpp"

namespace molchaos::sim {

inline constexpr std::size_t k_largest_kept_state = std::size_t{16} << 20;
inline constexpr std::size_t k_kept_bytes = std::size_t{512} << 20;

/// What a relaxed state depends on: the engine's layout (dimension, observer, record sizes) and
/// the parameters the constructor and relax() read. Restitution, shuffle, TC model, t_end and the
/// sampling are not among them.
std::string relaxed_state_key(const Parameters& p, const std::string& engine_layout);

/// The state kept under `key`, or null.
std::shared_ptr<const std::string> find_relaxed_state(const std::string& key);

/// Keeps `state` under `key` (within the bounds above). Safe to call from several threads.
void keep_relaxed_state(const std::string& key, std::string state);

/// Whether run() shares relaxed states (default on); off, every run relaxes itself. For tests
/// and for measuring what sharing saves. Clearing drops every kept state.
void share_relaxed_states(bool on);
bool relaxed_states_shared();
void clear_relaxed_states();
/// How many states are kept.
std::size_t kept_relaxed_states();

}  // namespace molchaos::sim
