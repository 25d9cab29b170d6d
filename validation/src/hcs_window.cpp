// Fit-window rule: transient by collision count, end by the break-down indicators.
#include "molchaos/validation/hcs_window.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "molchaos/sim/parameter_table.hpp"

namespace molchaos::validation {

double gamma_upper_tail(int terms, double y) {
  if (terms < 1) throw std::invalid_argument("terms: must be at least 1");
  if (y <= 0.0) return 1.0;
  double term = 1.0, sum = 1.0;
  for (int j = 1; j < terms; ++j) {
    term *= y / j;
    sum += term;
  }
  return std::exp(-y) * sum;
}

double gamma_upper_quantile(int terms, double probability) {
  if (!(probability > 0.0 && probability < 1.0))
    throw std::invalid_argument("probability: value " + sim::message_number(probability) +
                                " is outside the allowed range (0, 1)");
  // The tail falls monotonically from 1 at y = 0; bracket, then bisect.
  double lo = 0.0, hi = 1.0;
  while (gamma_upper_tail(terms, hi) > probability) hi *= 2.0;
  while (hi - lo > 1e-12 * hi) {
    const double mid = 0.5 * (lo + hi);
    (gamma_upper_tail(terms, mid) > probability ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

ModeThresholds equilibrium_mode_thresholds(int dimension, double per_sample) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: value " + std::to_string(dimension) +
                                " is not allowed; allowed values 2 or 3");
  const int d = dimension;
  return {gamma_upper_quantile(d, per_sample) / d,
          gamma_upper_quantile(d * d, per_sample) / (d * d)};
}

ModeThresholds WindowRule::default_thresholds() {
  static const ModeThresholds t =
      equilibrium_mode_thresholds(2, k_false_alarm_per_run / (2.0 * k_watched_samples));
  return t;
}

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
      b.previous = samples[i - 1].t;
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
                sim::message_number(rule.start_collisions_per_particle) + " collisions per particle)";
    return w;
  }
  w.breakdown = detect_breakdown(samples, rule);
  w.t_stop = w.breakdown.detected ? w.breakdown.time : samples.back().t;
  w.valid = w.t_stop > w.t_start;
  if (!w.valid) w.message = "the homogeneous cooling state broke down before the transient ended";
  return w;
}

std::string window_rule_line(const WindowRule& rule) {
  return fmt::format(
      "# window: from the first sample with at least {} collisions/particle to the first of two "
      "consecutive samples each with density mode > {} or velocity mode > {} (that sample "
      "included), else to the last sample\n",
      rule.start_collisions_per_particle, rule.density_mode_threshold,
      rule.velocity_mode_threshold);
}

}  // namespace molchaos::validation
