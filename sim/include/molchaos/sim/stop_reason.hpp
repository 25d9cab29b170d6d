// Why a run ended: an enum for code to test, and the text written to the CSV header
// (`# stop_reason = ...`), which for a collapse or a dead-lock names the time and the threshold.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace molchaos::sim {

enum class StopReason {
  t_end,            // reached the end of the run
  max_collisions,   // Parameters::max_collisions (or the engine's collision limit)
  min_temperature,  // Parameters::min_temperature
  collapse,         // inelastic collapse (see k_collapse_collisions)
  stalled,          // a numerical dead-lock (see k_stall_events)
};

/// Collapse: this many consecutive collisions, each less than 1e-10 mean free times after a
/// previous collision of one of its particles.
constexpr std::uint64_t k_collapse_collisions = 100000;
/// Dead-lock guard: this many consecutive events at one time without a collision.
constexpr std::uint64_t k_stall_events = 10'000'000;

/// The reason's name: "t_end", "max_collisions", "min_temperature", "collapse", "stalled".
std::string_view to_string(StopReason reason);

/// The CSV text: the name, and for collapse and stalled ": <what happened> at t = <t_stop>".
std::string describe(StopReason reason, double t_stop);

/// The reason a CSV text (describe()'s output) names, or nothing.
std::optional<StopReason> parse_stop_reason(std::string_view text);

}  // namespace molchaos::sim
