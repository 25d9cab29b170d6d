// The numbers the paper prints, defined once and used by name. Each is a claim that the suite
// checks against its own derivation (paper_checks.hpp); the suite computes with its own values and
// uses these only where it reproduces the paper's way of evaluating something.
#pragma once

namespace molchaos::theory {

/// Coefficients of μ2/μ2(0,0) = 1 + (3/16) a2 − (63/40) b (paper Eq. (21)).
inline constexpr double k_paper_coefficient_a2 = 3.0 / 16.0;
inline constexpr double k_paper_coefficient_b = -63.0 / 40.0;

/// The dyad factor of the paper's Eq. (15), D̂ = 3 r̂r̂ − U (3 is the 3D traceless value).
inline constexpr double k_paper_dyad_factor = 3.0;

/// Prefactor c of the paper's Eq. (22), 1/τ0 = c g2 σ^{d−1} n √(2T0/m) μ2 (printed 1/3).
inline constexpr double k_paper_tau0_prefactor = 1.0 / 3.0;

/// Prefactor c of the paper's ω0 = c g2 σ^{d−1} n √(πT0/m) (printed 1/3).
inline constexpr double k_paper_omega0_prefactor = 1.0 / 3.0;

/// Divisor c of the paper's temperature definition, Eq. (10): T = m/(c n) ∫ v² f (printed 3).
inline constexpr double k_paper_temperature_divisor = 3.0;

}  // namespace molchaos::theory
