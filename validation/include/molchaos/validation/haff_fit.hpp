// Haff's-law fit T(t) = T0/(1 + t/τ0)² to a simulated temperature series over a window chosen by
// a rule (hcs_window.hpp), by GSL nonlinear least squares on relative residuals.
#pragma once

#include <string>
#include <vector>

#include "molchaos/sim/result.hpp"

namespace molchaos::validation {

struct HaffFit {
  bool ok = false;
  std::string message;  ///< why a fit failed
  double T0 = 0.0, T0_error = 0.0;
  double tau0 = 0.0, tau0_error = 0.0;
  /// τ0 referred to the initial temperature T0 = 1: the slope of 1/√T is 1/(√T0 τ0), so
  /// τ0(T0 = 1) = √T0 · τ0. This is the τ0 that theory predicts for a gas started at T = 1.
  double tau0_unit = 0.0, tau0_unit_error = 0.0;
  double t_start = 0.0, t_stop = 0.0;
  std::size_t points = 0;
  double rms_relative_residual = 0.0;
};

/// Fits the samples with t_start ≤ t ≤ t_stop. Errors are the fit's standard deviations from the
/// covariance scaled by the residual variance (samples of one run are correlated in time, so the
/// ensemble's scatter, not these, is the honest error of an ensemble mean).
HaffFit fit_haff(const std::vector<sim::Sample>& samples, double t_start, double t_stop);

}  // namespace molchaos::validation
