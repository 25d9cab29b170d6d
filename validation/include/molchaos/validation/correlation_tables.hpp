// The tables of the correlation study as plain values (figures/ and the report read these):
// contact moments per gas, pair correlation functions, the cooling rate taken apart, the
// ansatz's fits at contact, and the verdict on the two routes to b.
#pragma once

#include <string>
#include <vector>

#include "molchaos/validation/figure_data.hpp"

namespace molchaos::validation {

/// One gas at one state point: collision averages over the homogeneous-cooling window.
struct ContactMomentRow {
  int dimension = 2;
  double density = 0.0, restitution = 0.0;
  std::string mode;  ///< "none" (original); "flux" or "dsmc" (the molecular-chaos references)
  int runs = 0;
  Measurement omega_over_enskog, gn2_over_4T, c1e_c2e, c1_dot_c2, a2, A;
  double impact_chi2 = 0.0;  ///< flatness of the impact-parameter histogram (0 if not filled)
  int impact_dof = 0;
};

/// One bin of one gas's impact-parameter histogram at one state point, s = (1 − (ĝ·e)²)^((d−1)/2)
/// of the colliding pairs in the homogeneous-cooling window: uniform on [0, 1) under molecular
/// chaos, so every fraction is 1/bins there.
struct ImpactParameterRow {
  int dimension = 2;
  double density = 0.0, restitution = 0.0;
  std::string mode;
  int runs = 0;
  double s_lo = 0.0, s_hi = 0.0;
  Measurement fraction;  ///< of the collisions in [s_lo, s_hi): mean ± standard error over runs
  /// The run-to-run variance of the fraction over the multinomial variance p(1 − p)/collisions:
  /// near 1 when the collisions' impact parameters are independent draws (then the χ² is exact).
  double scatter_over_multinomial = 0.0;
  /// Pearson χ² of the point's pooled counts against flat (the same on each bin of the point).
  double flatness_chi2 = 0.0;
  int flatness_dof = 0;
  double flatness_p = 1.0;
};

/// One r bin of the pair correlations of one gas at one time.
struct PairCorrelationRow {
  int dimension = 2;
  double density = 0.0, restitution = 0.0;
  std::string mode;
  double tau = 0.0;  ///< collisions per particle since t = 0 (mean over the snapshots)
  int snapshots = 0;
  std::string side;  ///< "all", "approaching", "receding"
  double r_lo = 0.0, r_hi = 0.0;
  Measurement g, G_par, G_perp;  ///< errors as in pair_correlations.hpp (independent pairs)
  /// from the snapshots' scatter
  double g_snapshot_error = 0.0, G_par_snapshot_error = 0.0, G_perp_snapshot_error = 0.0;
  double pairs = 0.0;
};

/// The cooling rate ζ = ω·(1 − ε²)·⟨(v12·e)²⟩/(4T)·ω-normalisation, original over chaos, paired by
/// seed: A_orig/A_chaos against (W_chaos·Y_chaos)/(W_orig·Y_orig), and the two factors' logs.
struct CoolingDecompositionRow {
  int dimension = 2;
  double density = 0.0, restitution = 0.0;
  int pairs = 0;
  Measurement A_ratio;          ///< A_orig/A_chaos, directly fitted
  Measurement product_ratio;    ///< (W Y)_chaos/(W Y)_orig
  Measurement difference;       ///< A_ratio − product_ratio, paired
  Measurement log_frequency;    ///< ln(W_chaos/W_orig): the collision-frequency deficit
  Measurement log_dissipation;  ///< ln(Y_chaos/Y_orig): the energy-loss-per-collision deficit
};

/// One amplitude obtained two ways from the same runs, paired by seed.
struct RoutePair {
  Measurement cooling, contact, difference;
  double covariance = 0.0;  ///< covariance of the two means (same runs)
  int pairs = 0;
};

/// Shifts at contact (original − chaos, a2 difference removed) fitted by the ansatz.
struct AnsatzFitRow {
  int dimension = 2;
  double density = 0.0, restitution = 0.0;
  int pairs = 0;
  Measurement shift_P, shift_Q, shift_W, shift_Y;
  // One amplitude, the printed dyad 3r̂r̂ − U.
  Measurement b;
  double chi2_one = 0.0;                                                  ///< 3 dof
  double residual_P = 0, residual_Q = 0, residual_W = 0, residual_Y = 0;  ///< in standard errors
  // Two amplitudes: longitudinal β∥ and transverse β⊥ (printed: β∥ = 2b, β⊥ = −b).
  Measurement beta_par, beta_perp;
  double beta_covariance = 0.0;
  double chi2_two = 0.0;  ///< 2 dof
  // The two routes to b (printed dyad, linear order), paired by seed: from the cooling rate and
  // from the contact dyad 3(c1·e)(c2·e) − c1·c2.
  RoutePair b_routes;
  // The two routes to β∥ (two-amplitude form): from the cooling rate (which depends on β∥ only)
  // and from the longitudinal contact moment ⟨(c1·e)(c2·e)⟩ alone.
  RoutePair beta_par_routes;
};

/// One claim of the study for the report: what is claimed, the verdict, the number deciding it.
struct StudyClaim {
  std::string claim;
  std::string verdict;
  Measurement deciding;
  std::string note;  ///< what the deciding number is
};

/// The global verdict on the two routes to b.
struct BRoutesVerdict {
  int points = 0;
  Measurement ratio;        ///< b_cooling/b_contact, weighted fit through the origin
  double chi2_equal = 0.0;  ///< χ² of b_cooling = b_contact over the points (dof = points)
  double p_value = 1.0;
  std::string verdict;    ///< "consistent" or "inconsistent"
  std::string statement;  ///< one sentence with the numbers
};

}  // namespace molchaos::validation
