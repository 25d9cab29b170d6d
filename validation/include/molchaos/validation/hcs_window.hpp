// The rule that picks the Haff fit window of each run from the run itself: after the initial
// transient, before the homogeneous cooling state breaks down.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "molchaos/sim/result.hpp"

namespace molchaos::validation {

struct WindowRule {
  /// Transient: the fit starts once every particle has collided this many times on average
  /// (a2 relaxes to its HCS value within a few collisions per particle).
  double start_collisions_per_particle = 3.0;
  /// Break-down: the largest-scale density fluctuation |ρ_k|²/N (1 for an ideal homogeneous gas)
  /// or momentum fluctuation |j_k|²/(N d T) (1 without velocity correlations) exceeds these
  /// thresholds at two consecutive samples. In a homogeneous gas each indicator averages
  /// exponential variables of mean ≲ 1 (d for the density, d² for the momentum), so a false
  /// alarm at 5 has probability e^{−10}·11 ≈ 5e−4 (density, d = 2) per independent sample.
  double density_mode_threshold = 5.0;
  double velocity_mode_threshold = 5.0;
};

struct Breakdown {
  bool detected = false;
  double time = 0.0;      ///< first of the two consecutive samples above threshold
  std::string indicator;  ///< "density_mode" or "velocity_mode"
};

struct FitWindow {
  double t_start = 0.0;
  double t_stop = 0.0;
  Breakdown breakdown;
  bool valid = false;
  std::string message;
};

Breakdown detect_breakdown(const std::vector<sim::Sample>& samples, const WindowRule& rule);
FitWindow choose_window(const std::vector<sim::Sample>& samples, std::int64_t particles,
                        const WindowRule& rule);

}  // namespace molchaos::validation
