// The data types validation/ produces for figures/ and the report: plain values, no behaviour.
// figures/ depends on this header only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "molchaos/theory/estimate.hpp"

namespace molchaos::validation {

/// A number with its uncertainty (standard error of an ensemble mean, or a fit's standard
/// deviation, or a quadrature error estimate — the producer says which): the suite's one
/// value±error type, shared with the theory library.
using Measurement = theory::Estimate;

/// One temperature curve T(t) (t > 0), e.g. one randomization mode averaged over its runs.
struct TemperatureCurve {
  std::string label;            ///< legend text, e.g. "original gas (no shuffle)"
  std::vector<double> t;        ///< physical time
  std::vector<double> T;        ///< temperature T/T0 (ensemble mean)
  std::vector<double> T_error;  ///< standard error of the mean (0 for a single run)
  bool is_theory = false;       ///< a Haff's-law line rather than simulation data
  std::string mode;             ///< the gas ("none", "paper", "flux"; its colour); empty for theory
};

/// Fig. 3 of the paper: T(t) at ε = 0.93, n = 0.05, N = 5000.
struct Fig3Data {
  std::string title;
  std::vector<TemperatureCurve> curves;  ///< simulations and Haff's-law lines
  /// Lower panel: T/T_Haff − 1 of each gas (ensemble mean ± SE over runs, in `T`, `T_error`),
  /// against Haff's law with the kinetic-theory τ0 (is_theory = true) and with the gas's own
  /// fitted τ0 (is_theory = false).
  std::vector<TemperatureCurve> deviations;
  std::optional<double> clustering_onset;  ///< detected break-down time of the original gas
  double inset_log_t_min = 2.5;            ///< inset range in ln t
  double inset_log_t_max = 3.0;
};

/// One point of Fig. 4: A = τ0(1 − ε²) at one (n, ε, mode).
struct APoint {
  double restitution = 0.0;
  Measurement A;
  int runs = 0;
};

/// A straight line a + b·ε fitted by least squares, with standard errors.
struct LinearFit {
  double intercept = 0.0, intercept_error = 0.0;
  double slope = 0.0, slope_error = 0.0;
  double chi2_per_dof = 0.0;
};

/// One data set of a Fig. 4 panel (e.g. "original", "randomized (flux)").
struct ASeries {
  std::string label;
  std::string mode;  ///< "none", "paper", "flux"
  std::vector<APoint> points;
  std::optional<LinearFit> fit;
  /// The slope's error by the jackknife over seeds, scaled as the fit's by √(χ²/dof) > 1: the
  /// runs of one seed at every ε start from the same relaxed state, which the fit's own error
  /// ignores (shared_seed_fit.hpp); 0 where a point has fewer than two runs.
  double slope_error_over_seeds = 0.0;
};

/// One panel of Fig. 4 (one density).
struct Fig4Panel {
  double density = 0.0;
  std::vector<ASeries> series;
  std::vector<double> theory_restitution;  ///< kinetic-theory A(ε) curve, b = 0
  std::vector<double> theory_A;
};

struct Fig4Data {
  std::string title;
  std::vector<Fig4Panel> panels;  ///< left: n = 0.05, right: n = 0.1
};

/// One gas's a2(ε) at one density: at each ε the mean ± standard error over runs of each run's a2
/// averaged over the homogeneous-cooling window of its Haff fit.
struct A2Series {
  std::string label;
  std::string mode;  ///< "none", "paper", "flux" (MD) or "dsmc"
  std::vector<double> restitution;
  std::vector<Measurement> a2;
  std::vector<int> runs;  ///< runs behind each a2 (its error means nothing below two)
};

/// One panel of the a2(ε) figure (one density): the gases and the Sonine theory on a fine ε grid.
struct A2Panel {
  double density = 0.0;
  std::vector<A2Series> series;
  std::vector<double> theory_restitution;
  std::vector<Measurement> first_sonine;  ///< van Noije & Ernst (the paper's Eq. (25))
  std::vector<Measurement> improved;      ///< with a2² and a3; error: the quadrature's
};

struct A2Data {
  std::string title;
  int dimension = 2;
  std::vector<A2Panel> panels;
};

/// b(ε) three ways, for one density.
struct BSeries {
  std::string
      label;  ///< e.g. "from A, paper's 63/40 and ω0", "from A, suite", "contact statistics"
  std::vector<double> restitution;
  std::vector<Measurement> b;
};

struct BPanel {
  double density = 0.0;
  std::vector<BSeries> series;
};

struct BData {
  std::string title;
  std::vector<BPanel> panels;
};

/// Positions and velocities of the original gas after the clustering onset, plus a coarse-grained
/// velocity field on a grid (cell centres and mean velocity per cell, empty cells omitted).
struct SnapshotData {
  std::string title;
  double time = 0.0;
  double box = 0.0;
  std::vector<double> x, y;                              ///< particle positions
  std::vector<double> speed;                             ///< |v| / sqrt(<v²>): colour
  std::vector<double> grid_x, grid_y, grid_vx, grid_vy;  ///< coarse-grained field (arrows)
};

/// Work–precision data for the theory quadrature: requested tolerance against CPU time and
/// the error actually reached.
struct WorkPrecisionPoint {
  double requested_tolerance = 0.0;
  double seconds = 0.0;
  double max_error_reached = 0.0;  ///< max over coefficients of |computed − exact|
  double max_error_estimate = 0.0;
};

struct WorkPrecisionData {
  std::string title;
  std::vector<WorkPrecisionPoint> points;
};

/// Cost and scatter of one system size in the simulation's work–precision measurement (the
/// flux-shuffled gas, where kinetic theory's A is exact). Relative quantities are over A_theory.
struct SimulationCostPoint {
  std::int64_t particles = 0;
  int seeds = 0;
  double cpu_seconds_per_run = 0.0;
  double relative_sd_per_run = 0.0;  ///< standard deviation of A over runs
  double relative_bias = 0.0;        ///< (mean A − A_theory)/A_theory
  double relative_bias_error = 0.0;  ///< its standard error
};

struct SimulationWorkPrecisionData {
  std::string title;
  std::vector<SimulationCostPoint> points;
  std::vector<double> targets{5e-3, 1e-3};  ///< relative standard errors aimed at
};

/// One row of the comparison table: theory, simulation and the paper on one number.
struct ComparisonRow {
  std::string quantity;
  std::optional<Measurement> theory;
  std::optional<Measurement> simulation;
  std::optional<double> paper;
  std::optional<double> difference_in_se;  ///< (simulation − theory)/combined standard error
  std::string verdict;                     ///< "reproduced", "not reproduced", "contradicted", ...
  std::string rule;                        ///< the rule that gave the verdict
  std::string note;
};

}  // namespace molchaos::validation
