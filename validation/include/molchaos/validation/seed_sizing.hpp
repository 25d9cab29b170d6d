// How many runs each state point of one gas needs for a target relative standard error of A.
// Sizing a point from its own scatter alone biases its error bar low: a point whose first few
// runs happen to scatter little stops there, and keeps an SE below its true one. So the scatter
// per run is read off a smooth model of the whole gas, and a point's own SE only tops it up.
#pragma once

#include <vector>

namespace molchaos::validation {

/// One state point of a gas (same mode, density, dimension and N; restitution varies).
struct PointScatter {
  double restitution = 0.0;
  int seeds = 0;             ///< seeds run so far (failed runs included: they were run)
  int runs = 0;              ///< runs that gave an A
  double relative_sd = 0.0;  ///< sample standard deviation of A per run / A (needs runs ≥ 2)
};

/// The gas's relative scatter per run at each point, in order: ln s as a weighted polynomial in
/// the restitution (quadratic from 4 points on, linear for 3, a constant for 2) over every point
/// with at least 2 runs, each weighted by its n − 1 degrees of freedom (var ln s ≈ 1/(2(n − 1))
/// for normal runs) after removing the small-sample bias E ln s − ln σ ≈ −1/(2(n−1)) − 1/(6(n−1)²).
/// A point left out of the fit (fewer than 2 runs) gets the model's value at its restitution;
/// with fewer than 2 usable points each point keeps its own scatter (0 when it has none).
std::vector<double> modelled_relative_scatter(const std::vector<PointScatter>& gas);

struct SeedSizing {
  double target_relative_error = 0.0015;
  int max_seeds = 192;
  /// At most this many times a point's seeds so far in one stage: an estimate from few runs is
  /// itself uncertain, and growing in steps keeps a low one from costing a large overshoot.
  int growth = 4;
  /// Runs needed = margin · (s/target)², s the modelled scatter.
  double margin = 1.1;
  /// No point is judged to meet the target with fewer runs: the scatter of 4 runs is uncertain by
  /// ±40 % (a factor 5 too low in 1 % of points), of 8 by ±27 %.
  int min_runs = 8;
};

/// The seeds each point should have in all after the next stage (never fewer than it has):
/// enough for the target at the modelled scatter, and where the point's own SE is still above
/// the target, enough at its own scatter too; at least min_runs.
std::vector<int> seeds_needed(const std::vector<PointScatter>& gas, const SeedSizing& sizing);

/// The relative scatter per run to report each point's SE(A)/A from once a gas has been grown to
/// a target: the larger of the point's own scatter and the gas's model, except where the point's
/// own runs reject the model as too large (their s²(n − 1)/model² below the 5 % quantile of χ² with
/// n − 1 degrees of freedom), which keep their own.
///
/// Growing until the SE meets a target is optional stopping: whether a point stops depends on the
/// scatter of its own runs, so the points that stop are those whose runs happened to scatter
/// little, and their own SE falls short of the true one (over the points of a gas by 4–7 % in rms,
/// at single points that stop after few runs by up to 15 %, for normal runs and for the MD's A
/// alike). The model pools every point of the gas and is little moved by one point's luck; taking
/// it where it is larger brings the spread of the points' means and their rms reported SE level
/// within about 1 % over a gas (single points within about ±10 %, on the large side where a point
/// stays at min_runs), while a point whose runs are many and clearly steadier than the smooth model
/// (a scatter that jumps with ε) keeps its own instead of the model's larger one. Points with fewer
/// than 2 runs keep their own (0). What single points keep of the bias, stopping_correction.hpp
/// measures and undoes.
std::vector<double> reported_relative_scatter(const std::vector<PointScatter>& gas);

}  // namespace molchaos::validation
