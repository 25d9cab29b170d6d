// Estimators of Haff's τ0 (referred to T0 = 1) from one run's temperature series over its
// homogeneous-cooling window. All four are exact for a series that follows Haff's law
// T = T0/(1 + t/τ0)²; they differ in how they weight the noise of a finite gas:
//
//   least_squares  the nonlinear fit of T(t) on relative residuals (haff_fit.hpp): what a
//                  reader of the paper's Fig. 3 would do. Samples are log-spaced in t, so the
//                  early part of the window counts most.
//   integrated     Haff's law integrated, d ln T/dt = −(2/τ0_unit)√T, over the window:
//                  τ0_unit = 2 ∫√T dt / ln(T_start/T_stop). The temperature falls by the same
//                  fraction per collision on average and collisions happen at a rate ∝ √T, so
//                  both the numerator and the denominator sum every collision of the window
//                  with equal weight — the efficient choice when collisions are independent.
//   secant         the straight line 1/√T = (1 + t/τ0)/√T0 through the window's two ends.
//   line           an unweighted least-squares line of 1/√T against t.
//
// The engine's temperature is exact between samples only at the samples, so ∫√T dt is taken
// piecewise under Haff's law between neighbouring samples (exact for a Haff series, second
// order otherwise): between y1 = 1/√T1 and y2 = 1/√T2, ∫ dt/y = Δt ln(y2/y1)/(y2 − y1).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "molchaos/sim/result.hpp"

namespace molchaos::validation {

enum class HaffEstimator { least_squares, integrated, secant, line };

inline constexpr std::array<HaffEstimator, 4> k_haff_estimators{
    HaffEstimator::least_squares, HaffEstimator::integrated, HaffEstimator::secant,
    HaffEstimator::line};

/// The estimator behind every A the suite reports: the one with the smallest scatter over
/// independent runs of the Fig. 4 ensembles (the reproduction's estimator table measures it).
inline constexpr HaffEstimator k_haff_estimator = HaffEstimator::integrated;

std::string_view to_string(HaffEstimator e);

/// ∫√T dt between two samples (t1, T1) and (t2, T2) under Haff's law between them, the rule of
/// the integrated estimator: what every ∫√T dt over a window (Enskog's collision count too) uses,
/// so that A, ω/ω_E and the energy loss per collision of one run obey A ∝ 1/(ω/ω_E · Y) exactly.
double root_temperature_integral(double t1, double T1, double t2, double T2);

struct Tau0Estimate {
  bool ok = false;
  std::string message;      ///< why there is no estimate
  double tau0_unit = 0.0;   ///< √T0·τ0: the τ0 of the same gas started at T = 1
};

/// τ0 referred to T0 = 1 from the samples with t_start ≤ t ≤ t_stop (at least 4, cooling).
Tau0Estimate estimate_tau0(HaffEstimator e, const std::vector<sim::Sample>& samples,
                           double t_start, double t_stop);

}  // namespace molchaos::validation
