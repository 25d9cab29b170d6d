// The stop reasons' names and CSV texts.
#include "molchaos/sim/stop_reason.hpp"

namespace molchaos::sim {

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
  }
  return "unknown";
}

std::string describe(StopReason reason, double t_stop) {
  switch (reason) {
    case StopReason::collapse:
      return "collapse: " + std::to_string(k_collapse_collisions) +
             " consecutive collisions less than 1e-10 mean free times apart at t = " +
             std::to_string(t_stop) + " (inelastic collapse; the TC model, tc > 0, avoids it)";
    case StopReason::stalled:
      return "stalled: " + std::to_string(k_stall_events) +
             " events without a collision at the same time t = " + std::to_string(t_stop) +
             " (a numerical dead-lock in the engine; please report it with the parameters)";
    default:
      return std::string(to_string(reason));
  }
}

std::optional<StopReason> parse_stop_reason(std::string_view text) {
  for (const StopReason reason :
       {StopReason::t_end, StopReason::max_collisions, StopReason::min_temperature}) {
    if (text == to_string(reason)) return reason;
  }
  for (const StopReason reason : {StopReason::collapse, StopReason::stalled}) {
    const std::string prefix = std::string(to_string(reason)) + ": ";
    if (text.substr(0, prefix.size()) == prefix) return reason;
  }
  return std::nullopt;
}

}  // namespace molchaos::sim
