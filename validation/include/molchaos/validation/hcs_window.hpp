// The rule that picks the Haff fit window of each run from the run itself: after the initial
// transient, before the homogeneous cooling state breaks down. The break-down thresholds follow
// from the equilibrium distribution of the largest-scale Fourier modes, not from a hand choice.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "molchaos/sim/result.hpp"

namespace molchaos::validation {

/// Probability that a sum of `terms` independent unit exponentials exceeds y (the upper tail of
/// Gamma(terms, 1)): e^{−y} Σ_{j<terms} y^j/j!.
double gamma_upper_tail(int terms, double y);

/// The y with gamma_upper_tail(terms, y) = probability (bisection to 1e-12 relative).
double gamma_upper_quantile(int terms, double probability);

/// Break-down thresholds of the two indicators of a sim::Sample for a false-alarm probability
/// `per_sample` of each indicator at one sample of a homogeneous (equilibrium) gas.
///
/// A Gaussian field has |f_k|² exponential about its mean, so over the d wavevectors 2π/L e_a:
///   density_mode  = (1/d) Σ_a |ρ_k|²/N         ~ S(k)·Gamma(d, 1)/d,
///   velocity_mode = (1/d) Σ_a Σ_b |j_k,b|²/(N d T) ~ Gamma(d², 1)/d²
/// (the velocity structure factors are 1 in equilibrium, for every component). Hard cores lower
/// the long-wavelength density fluctuations, S(k → 0) = k_B T (∂n/∂p)_T < 1, so S = 1 bounds the
/// density tail at every density. d = 2 has the heavier tails (fewer terms); the thresholds are
/// computed for the dimension given.
struct ModeThresholds {
  double density_mode = 0.0;
  double velocity_mode = 0.0;
};
ModeThresholds equilibrium_mode_thresholds(int dimension, double per_sample);

/// False-alarm budget of the default rule: at most this probability per run that a homogeneous
/// gas is declared broken down, by the union bound over both indicators at every one of
/// k_watched_samples samples (40 per decade over ten decades). Consecutive samples of the
/// largest-scale modes are strongly correlated (they relax on the sound and heat-diffusion times
/// of the box), so the true rate lies well below the bound.
inline constexpr double k_false_alarm_per_run = 1e-3;
inline constexpr int k_watched_samples = 400;

struct WindowRule {
  /// Transient: the fit starts once every particle has collided this many times on average
  /// (a2 relaxes to its HCS value within a few collisions per particle).
  double start_collisions_per_particle = 3.0;
  /// Break-down: the largest-scale density fluctuation |ρ_k|²/N (S(k) for a homogeneous gas)
  /// or momentum fluctuation |j_k|²/(N d T) (1 without velocity correlations) exceeds these
  /// thresholds at two consecutive samples. Defaults: equilibrium_mode_thresholds for d = 2
  /// (the heavier tail, so valid for d = 3 too) at k_false_alarm_per_run/(2 k_watched_samples)
  /// per sample and indicator: 8.2 and 5.3.
  double density_mode_threshold = default_thresholds().density_mode;
  double velocity_mode_threshold = default_thresholds().velocity_mode;

  static ModeThresholds default_thresholds();
};

struct Breakdown {
  bool detected = false;
  double time = 0.0;      ///< first of the two consecutive samples above threshold
  double previous = 0.0;  ///< the sample before it: the threshold was crossed in (previous, time]
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

/// The rule as a result file's header line ("# window: ...\n"), every threshold to the last
/// digit, so that a table's A can be recomputed from its runs' T(t) alone.
std::string window_rule_line(const WindowRule& rule);

}  // namespace molchaos::validation
