// Pair correlation functions of a snapshot: the radial distribution g(r) and the velocity
// correlations G∥(r) = ⟨(c1·r̂)(c2·r̂)⟩ and G⊥(r) = ⟨c1·c2 − (c1·r̂)(c2·r̂)⟩/(d − 1) over pairs at
// separation r, c = v/√(2T), split by approaching and receding pairs; ensemble means with errors.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "molchaos/sim/result.hpp"
#include "molchaos/validation/figure_data.hpp"

namespace molchaos::validation {

/// Which pairs a bin counts: all, approaching ((r1 − r2)·(v1 − v2) < 0) or receding.
enum class PairSide { all = 0, approaching = 1, receding = 2 };
inline constexpr std::array<PairSide, 3> k_pair_sides{PairSide::all, PairSide::approaching,
                                                      PairSide::receding};
const char* to_string(PairSide side);

/// Sums over the pairs of one snapshot in each bin [edges[k], edges[k+1]), per side.
struct PairBinSums {
  std::array<double, 3> pairs{}, sum_par{}, sum_perp{}, sum_par2{}, sum_perp2{};
};

struct SnapshotPairSums {
  double temperature = 0.0;
  std::vector<double> edges;
  std::vector<PairBinSums> bins;
  std::vector<double> uncorrelated_pairs;  ///< expected pairs per bin without correlations
  double all_pairs = 0.0;                  ///< N(N − 1)/2, the pairs a bin's count is drawn from
};

/// Bin edges from σ = 1 to r_max: `near` equal bins of width `near_width` from contact, then
/// `far` logarithmically spaced bins up to r_max.
std::vector<double> pair_grid(double r_max, int near, double near_width, int far);

/// The grid of every pair-correlation table: 10 bins of 0.05σ from contact (the collision's
/// imprint), then 16 logarithmic bins up to half the box side.
std::vector<double> default_pair_grid(double box);

/// The sums of one snapshot (positions in a periodic box of side snap.box), by a cell list whose
/// cells are at least the largest edge wide (all pairs when fewer than 3 cells fit per side).
/// Throws std::invalid_argument if the largest edge exceeds half the box.
SnapshotPairSums pair_sums(const sim::Snapshot& snap, int dimension,
                           const std::vector<double>& edges);

/// Ensemble estimate in one bin for one side. g = Σ pairs / Σ uncorrelated pairs with the binomial
/// error of each snapshot's count among its N(N − 1)/2 pairs, √(pairs (1 − pairs/all_pairs)):
/// exact for an ideal gas (the indicators of pairs in a shell of radius at most half the periodic
/// box are pairwise independent, also those sharing a particle), where √pairs overstates it by
/// 1/√(1 − p) for a shell holding a fraction p of the box (a third or more in the outer bins);
/// the gas's own structure (a compressibility below the ideal gas's)
/// makes the real scatter smaller still, which the error from the scatter of the snapshots beside
/// it measures. G∥, G⊥ = Σ products / Σ pairs with the error of a mean of independent pair
/// products. That error is exact under molecular chaos (products of different pairs are
/// uncorrelated when velocities are independent with zero mean, even if they share a particle),
/// so it is the one the test of G = 0 uses; with correlations it is a lower bound, and the error
/// from the scatter of the snapshots (ratio estimator, few snapshots: itself uncertain) is given
/// beside it.
struct PairCorrelationBin {
  double r_lo = 0.0, r_hi = 0.0;
  PairSide side = PairSide::all;
  Measurement g, G_par, G_perp;
  double g_snapshot_error = 0.0, G_par_snapshot_error = 0.0, G_perp_snapshot_error = 0.0;
  double pairs = 0.0;  ///< pairs counted over all snapshots
};

std::vector<PairCorrelationBin> combine_pair_sums(const std::vector<SnapshotPairSums>& snapshots,
                                                  int dimension);

/// Global χ² of the hypothesis G∥ = G⊥ = 0 over the bins of side `all` with an error, and its dof.
struct ChiSquare {
  double chi2 = 0.0;
  int dof = 0;
  double p_value = 1.0;  ///< upper tail probability
};
ChiSquare chi_square_zero_velocity_correlations(const std::vector<PairCorrelationBin>& bins);

/// Upper tail probability of χ² with dof degrees of freedom.
double chi_square_p_value(double chi2, int dof);

/// The standard normal score with the same tail probability as Student's t with dof degrees of
/// freedom: a mean over k runs divided by its estimated standard error is t-distributed with
/// k − 1 dof (heavy-tailed for k ≈ 8), so its square may enter a χ² only after this mapping.
double normal_score(double t, int dof);

/// Two-sided tail probability of Student's t with dof degrees of freedom: how often a mean over
/// dof + 1 runs lies |t| estimated standard errors or more from the true value (1 for dof = 0).
double student_p_two_sided(double t, int dof);

}  // namespace molchaos::validation
