// The share of the kinetic energy held by the coarse-grained flow (vortices) of the original gas
// during the homogeneous stage, against ε and n. Flow energy is not dissipated by collisions (a
// smooth flow adds only σ·∇u to a pair's relative velocity), so a share f of T in the flow slows
// Haff's cooling as if T were T(1 − f): dT/dt ∝ −(T(1 − f))^{3/2} stretches τ0, and A, by
// 1 + 3f/2 to first order. Compared with the measured A_orig/A_chaos − 1, this says how much of
// the original gas's slower cooling the vortices account for.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "molchaos/validation/figure_data.hpp"

namespace molchaos::validation {

struct FlowEnergySpec {
  std::int64_t particles = 5000;  ///< the paper's N: its box holds the flow of the paper's runs
  std::vector<double> densities{0.05, 0.1};
  std::vector<double> restitutions{0.80, 0.90, 0.96};
  int runs = 6;
  /// snapshot times in units of the kinetic-theory τ0: the window of the Fig. 4 fits (t ≤ 4τ0)
  std::vector<double> times_in_tau0{1.0, 2.0, 3.0, 4.0};
  int cells = 10;  ///< ~50 particles per cell at N = 5000 and n = 0.05 (box 316σ: cell 32σ)
  std::uint64_t base_seed = 2024;
};

struct FlowEnergyPoint {
  double density = 0, restitution = 0;
  /// (T_flow − noise)/T averaged over the snapshot times, run mean ± standard error
  Measurement flow_fraction;
};

std::vector<FlowEnergyPoint> flow_energy_study(const FlowEnergySpec& spec = {});

}  // namespace molchaos::validation
