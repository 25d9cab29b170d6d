// When the homogeneous cooling state breaks: the linear-hydrodynamics prediction
// (theory/hydrodynamics) against simulation, with no free parameter. One call runs the needed
// simulations (≲ 60 s on one core) and returns a table of predicted and measured quantities.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace molchaos::sim {
struct Sample;
}

namespace molchaos::validation {

struct BreakdownSpec {
  int dimension = 2;
  double density = 0.05;
  double restitution = 0.93;
  std::int64_t unstable_particles = 5000;  ///< box 316σ at n = 0.05, above L_c (190σ at ε = 0.93)
  std::int64_t stable_particles = 1125;    ///< box 150σ, below L_c
  int runs = 32;                           ///< independent runs per box
  double collisions_per_particle = 110.0;  ///< run length τ
  double snapshot_interval = 2.5;          ///< τ between snapshots
  /// growth rates are fitted where the predicted S⊥ lies in [2, this]: past the equilibrium
  /// start, before the flow energy of the fitted shell exceeds ~1 % of the thermal one
  double fit_max_transverse = 30.0;
  int max_norm2 = 25;  ///< shells |m|² ≤ this: every shell whose S⊥ departs from 1 visibly
  /// T's departure from Haff's law and the detector onset (the late, nonlinear regime)
  bool onset_rows = true;
  std::uint64_t base_seed = 9001;

  /// The compact set in d = 3 (see breakdown.cpp for the choice of its state point).
  static BreakdownSpec three_dimensional();
};

/// quantity, prediction, measurement ± standard error (jackknife over runs), and how each was
/// obtained. NaN where a side does not apply.
struct BreakdownRow {
  std::string quantity;
  double predicted = 0;
  double measured = 0;
  double measured_error = 0;
  std::string note;
  int dimension = 2;
  bool linear_regime = false;  ///< a growth rate or stationary level: the linear theory's claim
};

/// S⊥(k, τ) of one shell, the mean over the runs ± its standard error, against the linear
/// prediction at the same τ (collisions per particle).
struct StructureFactorCurve {
  int dimension = 2;
  double wavenumber = 0;
  double box = 0;  ///< L in σ; above or below L_c
  std::vector<double> tau, measured, error, predicted;
};

/// Runs the study; if `curves` is given, fills it with S⊥(τ) of the lowest shells of both boxes.
std::vector<BreakdownRow> breakdown_study(const BreakdownSpec& spec = {},
                                          std::vector<StructureFactorCurve>* curves = nullptr);

/// Collisions per particle τ = 2·collisions/N at time t, interpolated between samples.
double collisions_per_particle_at(const std::vector<sim::Sample>& samples, double t,
                                  double particles);

/// The table as Markdown (for the report).
std::string breakdown_markdown(const std::vector<BreakdownRow>& rows);

}  // namespace molchaos::validation
