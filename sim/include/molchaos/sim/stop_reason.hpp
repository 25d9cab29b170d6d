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
  max_events,       // the event bound that Parameters::max_collisions implies (engine.hpp)
  temperature_floor,  // T/T0 fell below k_temperature_floor, the floor of double precision
};

/// Collapse: this many consecutive collisions, each less than 1e-10 mean free times after a
/// previous collision of one of its particles.
constexpr std::uint64_t k_collapse_collisions = 100000;
/// Dead-lock guard: this many consecutive events at one time without a collision.
constexpr std::uint64_t k_stall_events = 10'000'000;

/// Event bound: a run with max_collisions = C stops after C * e * k_events_per_expected_event
/// events, e being the events per collision of a homogeneous gas at the run's density (the
/// collision, cell crossings or shell exits, stale predictions). A gas that has stopped colliding
/// (frozen, or drifting as a whole) then ends instead of crossing cells for ever.
constexpr std::uint64_t k_events_per_expected_event = 100;
/// Floor of double precision for T/T0: the engine's physical T is T_internal / theta^2 with
/// T_internal of order 1, so below about 1e-300 theta^2 overflows and velocities underflow.
constexpr double k_temperature_floor = 1e-300;

/// The reason's name: "t_end", "max_collisions", "min_temperature", "collapse", "stalled",
/// "max_events", "temperature_floor".
std::string_view to_string(StopReason reason);

/// The CSV text: the name, and for collapse, stalled, max_events and temperature_floor
/// ": <what happened> at t = <t_stop>".
/// tc: the run's TC duration, so that a collapse message says what helps (a TC model, or a longer
/// one).
std::string describe(StopReason reason, double t_stop, double tc = 0);

/// The reason a CSV text (describe()'s output) names, or nothing.
std::optional<StopReason> parse_stop_reason(std::string_view text);

}  // namespace molchaos::sim
