// The original and the randomized gases side by side through the break-down of the homogeneous
// cooling state (d = 2): at each snapshot time the transverse-velocity and density structure
// factors of the box's largest modes, the share of the thermal energy held by the coarse-grained
// flow, and (from the first run of each gas) the flow and density fields for the figure.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "molchaos/validation/figure_data.hpp"
#include "molchaos/validation/flow_field.hpp"

namespace molchaos::validation {

struct GasFieldSpec {
  std::int64_t particles = 5000;  ///< the paper's box (316σ at n = 0.05, above L_c = 190σ)
  double density = 0.05;
  double restitution = 0.93;
  std::vector<std::string> modes{"none", "paper", "flux"};
  int runs = 12;  ///< per gas; the same seeds for every gas (same initial states)
  std::vector<double> log_times{2.0, 3.0, 4.0, 5.0, 5.5, 6.0, 6.5, 7.0, 7.5, 8.0};
  /// rows of the flow-field figure; the first run of each gas goes on to the last of them
  std::vector<double> field_log_times{4.0, 6.0, 7.5, 9.0};
  int cells = 10;           ///< 50 particles per cell at N = 5000 (flow energy, density contrast)
  int field_cells = 24;     ///< grid of the figure's long-wave fields
  int field_max_norm2 = 5;  ///< the figure's fields keep the modes |m|² ≤ 5 (λ ≥ L/√5)
  /// the animation (fig_flow_field.gif): the first run of each of these gases, frames evenly in
  /// ln t from animation_first_log_time to the last of field_log_times (animation_log_times)
  std::vector<std::string> animation_modes{"none", "flux"};
  int animation_frames = 24;
  double animation_first_log_time = 2.0;  ///< homogeneous: no mode has grown yet
  /// the largest modes: shells |m|² ≤ 2, the ones unstable at N = 5000 (k < k⊥ ⇔ |m| < L/L_c)
  int max_norm2 = 2;
  std::uint64_t base_seed = 4711;
};

/// One gas at one time: the run mean ± standard error over the runs.
struct GasFieldPoint {
  double log_time = 0;
  double tau = 0;          ///< collisions per particle (run mean)
  Measurement transverse;  ///< S⊥ averaged over the wavevectors of shells |m|² ≤ max_norm2
  double transverse_predicted = 1;  ///< the same average by linear hydrodynamics at τ (1: shuffled)
  Measurement density;              ///< S(k) over the same wavevectors
  Measurement flow_fraction;        ///< (T_flow − noise)/T, noise = T·(occupied cells)/N
  Measurement density_contrast;  ///< variance of the particles per cell over its mean (1: Poisson)
};

struct GasFieldSeries {
  std::string mode;  ///< "none", "paper", "flux"
  std::vector<GasFieldPoint> points;
  /// [time][run]: the values behind `points`, for tests over windows of time
  std::vector<std::vector<double>> run_transverse, run_density;
};

struct GasFieldStudy {
  GasFieldSpec spec;
  double box = 0;
  std::vector<double> wavenumbers;  ///< of the shells used
  std::vector<GasFieldSeries> series;
  FlowFieldData fields;
  FlowFieldData animation;  ///< one row per frame, one column per animation mode
};

/// ln t of the animation's frames (empty if animation_frames = 0).
std::vector<double> animation_log_times(const GasFieldSpec& spec);

GasFieldStudy gas_field_study(const GasFieldSpec& spec = {});

/// Run mean ± standard error of S⊥ (of S) averaged, in each run, over lo ≤ ln t ≤ hi.
Measurement window_transverse(const GasFieldStudy& study, const GasFieldSeries& gas, double lo,
                              double hi);
Measurement window_density(const GasFieldStudy& study, const GasFieldSeries& gas, double lo,
                           double hi);

/// Growth of the density structure factor within each run: S averaged over ln t ≥ late_start
/// minus S averaged over ln t ≤ early_end; run mean ± standard error.
Measurement density_growth(const GasFieldStudy& study, const GasFieldSeries& gas, double early_end,
                           double late_start);

/// The series as CSV (one row per gas and time), with the spec as `#` header lines.
std::string gas_field_csv(const GasFieldStudy& study);

}  // namespace molchaos::validation
