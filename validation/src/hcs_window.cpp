// Fit-window rule: transient by collision count, end by the break-down indicators.
#include "molchaos/validation/hcs_window.hpp"

namespace molchaos::validation {

Breakdown detect_breakdown(const std::vector<sim::Sample>& samples, const WindowRule& rule) {
  Breakdown b;
  auto above = [&](const sim::Sample& s) -> const char* {
    if (s.density_mode > rule.density_mode_threshold) return "density_mode";
    if (s.velocity_mode > rule.velocity_mode_threshold) return "velocity_mode";
    return nullptr;
  };
  for (std::size_t i = 1; i + 1 < samples.size(); ++i) {
    const char* now = above(samples[i]);
    if (now && above(samples[i + 1])) {
      b.detected = true;
      b.time = samples[i].t;
      b.indicator = now;
      return b;
    }
  }
  return b;
}

FitWindow choose_window(const std::vector<sim::Sample>& samples, std::int64_t particles,
                        const WindowRule& rule) {
  FitWindow w;
  if (samples.size() < 2) {
    w.message = "no samples";
    return w;
  }
  const double needed = rule.start_collisions_per_particle * static_cast<double>(particles) / 2.0;
  bool found = false;
  for (const auto& s : samples)
    if (static_cast<double>(s.collisions) >= needed) {
      w.t_start = s.t;
      found = true;
      break;
    }
  if (!found) {
    w.message = "run ended before the transient (" +
                std::to_string(rule.start_collisions_per_particle) + " collisions per particle)";
    return w;
  }
  w.breakdown = detect_breakdown(samples, rule);
  w.t_stop = w.breakdown.detected ? w.breakdown.time : samples.back().t;
  w.valid = w.t_stop > w.t_start;
  if (!w.valid) w.message = "the homogeneous cooling state broke down before the transient ended";
  return w;
}

}  // namespace molchaos::validation
