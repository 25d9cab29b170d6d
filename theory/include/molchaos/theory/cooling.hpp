// Haff's law for the homogeneous cooling state in d dimensions, from the Enskog–Boltzmann
// equation (derivation in doc/theory.md).
//
// Units: σ = m = k_B = 1. Temperature T = m⟨v²⟩/d (each translational degree of freedom carries
// T/2; this is the temperature of the paper's v0 = √(2T/m) and of Enskog's frequency).
// With f(v) = n v0^{−d} f̃(v/v0) the second moment of the Enskog–Boltzmann equation gives
//     dT/dt = −(2/d) g2 σ^{d−1} n v0 μ2 T,
// hence T(t) = T0 / (1 + t/τ0)² with
//     1/τ0 = (1/d) g2 σ^{d−1} n √(2T0/m) μ2            (the paper prints 1/3, its d = 3 value)
// and, with μ2 = (1 − ε²) μ̂_d [1 + (3/16) a2 + … + c_b b + …] (μ̂_2 = √(2π)/2, μ̂_3 = √(2π)),
//     τ0 = A/(1 − ε²),   1/A = ω0 · μ2/μ2(0,0),   ω0 = (1/d) g2 σ^{d−1} n √(2T0/m) μ̂_d,
// so ω0 = ½ g2 σ n √(πT0/m) for disks and ⅔ g2 σ² n √(πT0/m) for spheres.
#pragma once

#include <optional>

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/estimate.hpp"

namespace molchaos::theory {

struct CoolingInputs {
  int dimension = 2;
  double density = 0.05;
  double restitution = 0.9;
  double initial_temperature = 1.0;
  double correlation_b = 0.0;  ///< the paper's b = χ(σ)/g2(σ)
  double dyad_factor = k_paper_dyad_factor;
  std::optional<double> a2;  ///< default: first-Sonine a2(ε)
  QuadratureOptions quadrature{};
};

struct CoolingPrediction {
  double packing_fraction = 0.0;
  double g2 = 0.0;
  double a2 = 0.0;
  /// Uncertainty of a2 carried into μ2/μ2(0,0), A and τ0: for the default first-Sonine a2, how
  /// far the suite's own quadrature of the moment equations confirms the closed form
  /// (a2_from_moments by the Gauss rules, the error of the first_sonine level of sonine_hcs.hpp);
  /// 0 for an a2 given as input.
  double a2_error = 0.0;
  Estimate mu2;                             ///< μ2(a2, b; ε) by quadrature (g2 excluded)
  Estimate mu2_ratio;                       ///< μ2 / μ2(0,0)
  double omega0 = 0.0;                      ///< ω0 (closed form, derived above)
  Estimate tau0;                            ///< +inf at ε = 1 (no cooling)
  Estimate A;                               ///< A = τ0 (1 − ε²) with the given a2 and b
  Estimate A_uncorrelated;                  ///< A with b = 0: a gas without velocity correlations
  double enskog_collision_frequency = 0.0;  ///< per particle, at T0
};

/// Reduced prefactor μ̂_d = μ2(0,0; ε)/(1 − ε²) in closed form: √(2π)/2 (d = 2), √(2π) (d = 3).
double mu2_maxwell_prefactor(int dimension);

/// ω0 of the header comment.
double cooling_frequency_omega0(int dimension, double density, double initial_temperature);

/// Bound on the relative rounding of ω0 as cooling_frequency_omega0 computes it, the typed
/// density's rounding to a double included (counted in cooling.cpp); it grows as η/(1 − η) towards
/// close packing, where 1 − η cancels.
double omega0_relative_rounding(int dimension, double density);

/// A = 1/(ω0 · μ2/μ2(0,0)) with its error: the ratio's (relative error carried over), the
/// rounding of ω0 and that of the product and the reciprocal.
Estimate cooling_prefactor_A(int dimension, double density, double initial_temperature,
                             const Estimate& mu2_ratio);

/// ln t after `collisions` collisions per particle on Haff's law, τ = ω_E(T0) τ0 ln(1 + t/τ0)
/// (ω_E ∝ √T = √T0/(1 + t/τ0)), so t = τ0 (e^x − 1) with x = τ/(ω_E(T0) τ0). Computed as
/// ln τ0 + x + ln(1 − e^{−x}), finite where t itself overflows a double (x beyond ~709).
double log_time_after_collisions(double collisions, double tau0,
                                 double initial_collision_frequency);

/// Enskog's collision frequency per particle, ω = g2 n σ^{d−1} |S^{d−2}|-weighted ⟨|v12|⟩:
/// 2 n σ g2 √(πT/m) for disks, 4 n σ² g2 √(πT/m) for spheres.
double enskog_collision_frequency(int dimension, double density, double temperature);

/// Haff's law T0 / (1 + t/τ0)².
inline double haff_temperature(double t, double initial_temperature, double tau0) {
  const double s = 1.0 + t / tau0;
  return initial_temperature / (s * s);
}

/// Everything the theory predicts for one state point.
CoolingPrediction predict_cooling(const CoolingInputs& inputs);

}  // namespace molchaos::theory
