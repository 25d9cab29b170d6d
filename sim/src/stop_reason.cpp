// The stop reasons' names and CSV texts.
#include "molchaos/sim/stop_reason.hpp"

#include <iomanip>
#include <sstream>

namespace molchaos::sim {
namespace {

// A time or temperature with 6 significant digits ("1e+23", "3.25e-301", "200").
std::string message_time(double x) {
  std::ostringstream text;
  text << std::setprecision(6) << x;
  return text.str();
}

}  // namespace

std::string_view to_string(StopReason reason) {
  switch (reason) {
    case StopReason::t_end:
      return "t_end";
    case StopReason::max_collisions:
      return "max_collisions";
    case StopReason::min_temperature:
      return "min_temperature";
    case StopReason::collapse:
      return "collapse";
    case StopReason::stalled:
      return "stalled";
    case StopReason::max_events:
      return "max_events";
    case StopReason::temperature_floor:
      return "temperature_floor";
  }
  return "unknown";
}

std::string describe(StopReason reason, double t_stop, double tc) {
  switch (reason) {
    case StopReason::collapse:
      return "collapse: " + std::to_string(k_collapse_collisions) +
             " consecutive collisions less than 1e-10 mean free times apart at t = " +
             std::to_string(t_stop) +
             (tc > 0 ? " (inelastic collapse although the TC model is on: tc = " +
                           message_time(tc) +
                           " is shorter than the time between these collisions; a larger tc "
                           "avoids it)"
                     : std::string(" (inelastic collapse; the TC model, simulate --tc > 0, avoids it)"));
    case StopReason::stalled:
      return "stalled: " + std::to_string(k_stall_events) +
             " events without a collision at the same time t = " + std::to_string(t_stop) +
             " (a numerical dead-lock in the engine; please report it with the parameters)";
    case StopReason::max_events:
      return "max_events: the event bound of max_collisions (" +
             std::to_string(k_events_per_expected_event) +
             " times the events a homogeneous gas needs for them) reached at t = " +
             message_time(t_stop) +
             " (the gas has nearly stopped colliding; events are cell crossings)";
    case StopReason::temperature_floor:
      return "temperature_floor: T/T0 fell below " + message_time(k_temperature_floor) +
             ", the floor of double precision, at t = " + message_time(t_stop) +
             " (the gas cannot cool further in double precision)";
    default:
      return std::string(to_string(reason));
  }
}

std::optional<StopReason> parse_stop_reason(std::string_view text) {
  for (const StopReason reason :
       {StopReason::t_end, StopReason::max_collisions, StopReason::min_temperature}) {
    if (text == to_string(reason)) return reason;
  }
  for (const StopReason reason : {StopReason::collapse, StopReason::stalled,
                                  StopReason::max_events, StopReason::temperature_floor}) {
    const std::string prefix = std::string(to_string(reason)) + ": ";
    if (text.substr(0, prefix.size()) == prefix) return reason;
  }
  return std::nullopt;
}

}  // namespace molchaos::sim
