// Structure factors and coarse-grained fields of one snapshot: the density S(k) and the
// longitudinal and transverse velocity structure factors S∥(k), S⊥(k) on the box's wavevector
// lattice, grouped by |k|, and the flow (coarse-grained velocity) part of the temperature.
#pragma once

#include <vector>

#include "molchaos/sim/result.hpp"

namespace molchaos::validation {

/// All lattice wavevectors k = (2π/L) m with the same |m|² (one of each ±k pair).
///   S(k)  = ⟨|Σ_i e^{ik·r_i}|²⟩/N                 (→ k_B T (∂n/∂p)_T as k → 0 in equilibrium)
///   S∥(k) = ⟨|Σ_i (k̂·v_i) e^{ik·r_i}|²⟩/(N T)      (1 in equilibrium)
///   S⊥(k) = ⟨|Σ_i (v_i − k̂ k̂·v_i) e^{ik·r_i}|²⟩/(N T (d−1))   (1 in equilibrium)
/// with T = Σ m v²/(N d) of the snapshot, the average over the shell's wavevectors.
struct StructureShell {
  int lattice_norm2 = 0;  ///< |m|²
  double wavenumber = 0;  ///< |k| = 2π|m|/L
  int wavevectors = 0;    ///< in the half space
  double density = 0;     ///< S(k)
  double longitudinal = 0;
  double transverse = 0;
};

/// Shells with 0 < |m|² ≤ max_norm2, ordered by |m|. Snapshot positions/velocities are d·N
/// particle-major arrays (sim::Snapshot); dimension = positions.size()/velocities: passed.
std::vector<StructureShell> structure_factors(const sim::Snapshot& snapshot, int dimension,
                                              int max_norm2);

/// Velocity and density on a grid of cells^d cells (row-major, x fastest).
struct CoarseField {
  int dimension = 2;
  int cells = 0;  ///< per side
  double cell_width = 0;
  std::vector<double> number;    ///< particles per cell
  std::vector<double> velocity;  ///< d per cell: mean velocity (0 in an empty cell)
  double temperature = 0;        ///< T = Σ v²/(N d)
  /// T_flow = Σ_cells N_c |u_c|²/(N d): the kinetic energy of the coarse-grained flow. A gas
  /// without velocity correlations has T_flow = T·(occupied cells)/N from sampling noise alone.
  double flow_temperature = 0;
  int occupied_cells = 0;
};

CoarseField coarse_grain(const sim::Snapshot& snapshot, int dimension, int cells);

/// Vorticity ∂x u_y − ∂y u_x of a d = 2 field by central differences on the periodic grid.
std::vector<double> vorticity(const CoarseField& field);

}  // namespace molchaos::validation
