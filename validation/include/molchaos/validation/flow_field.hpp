// Coarse-grained flow and density fields of d = 2 snapshots, as plain data for the flow-field
// figure (figures/render_flow_field): vortices first, then density clusters, in the original gas
// and beside it a randomized one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace molchaos::sim {
struct Snapshot;
}

namespace molchaos::validation {

/// One snapshot on a cells × cells grid (row-major, x fastest): density relative to the mean,
/// mean velocity in units of the thermal √T of the snapshot, vorticity in the same units per σ.
/// The noise levels are the standard deviations the density and the vorticity would have at a
/// grid point in a gas without correlations (uniform positions, S(k) = 1, velocities independent
/// of them), the unit in which the figure compares gases and times.
struct FlowFieldPanel {
  std::string title;
  double box = 0;
  int cells = 0;
  std::vector<double> relative_density, vx, vy, vorticity;
  double density_noise = 0, vorticity_noise = 0;
};

/// Rows of panels: one row per time, one column per gas.
struct FlowFieldData {
  std::vector<std::string> column_titles;
  std::vector<std::vector<FlowFieldPanel>> rows;
};

struct FlowFieldSpec {
  std::int64_t particles = 5000;
  double density = 0.05;
  double restitution = 0.93;
  std::vector<double> log_times{3.0, 7.0, 9.5};  ///< ln t of the snapshots
  std::vector<std::string> modes{"none", "flux"};
  int cells = 10;  ///< ~50 particles per cell at N = 5000: flow above the noise
  std::uint64_t seed = 7;
};

/// One panel from a d = 2 snapshot coarse-grained on cells × cells.
FlowFieldPanel flow_field_panel(const sim::Snapshot& snapshot, int cells, std::string title);

/// One panel of the hydrodynamic fields only: density, velocity and vorticity built from the
/// Fourier modes with |m|² ≤ max_norm2 (wavelengths ≥ L/√max_norm2), sampled at the centres of
/// cells × cells. The particle noise of the shorter waves, which hides the flow in coarse cells at
/// N = 5000, is left out: a gas without correlations shows only the few long waves' noise.
FlowFieldPanel long_wave_panel(const sim::Snapshot& snapshot, int cells, int max_norm2,
                               std::string title);

/// Runs one simulation per mode (the same seed, so the same initial state) and coarse-grains
/// its snapshots.
FlowFieldData flow_field_data(const FlowFieldSpec& spec = {});

}  // namespace molchaos::validation
