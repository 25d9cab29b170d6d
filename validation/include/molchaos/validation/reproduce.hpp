// The whole reproduction of the paper as one computation: the ensembles behind Figs. 3 and 4,
// the elastic-limit check of every randomization mode, b(ε) three ways, and each claim of the
// paper (and each finding of the suite) with its verdict. Produces data only; figures/ renders it
// and report.hpp writes it out. How to add a claim: the top of validation/src/reproduce.cpp.
#pragma once

#include <string>
#include <vector>

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/validation/breakdown.hpp"
#include "molchaos/validation/correlation_study.hpp"
#include "molchaos/validation/ensemble.hpp"
#include "molchaos/validation/figure_data.hpp"
#include "molchaos/validation/flow_energy.hpp"
#include "molchaos/validation/gas_fields.hpp"
#include "molchaos/validation/sweep.hpp"

namespace molchaos::validation {

struct ReproduceConfig {
  bool quick = false;
  std::int64_t particles = 5000;
  std::vector<double> densities{0.05, 0.1};
  std::vector<double> restitutions{0.80, 0.82, 0.84, 0.86, 0.88, 0.90, 0.92, 0.94, 0.96, 0.98};
  int seeds = 8;
  /// Points whose A has a larger relative standard error get more seeds (up to max_seeds).
  double target_relative_error = 0.0015;
  int max_seeds = 192;
  /// The ensembles' base seed (Figs. 3 and 4, DSMC, the elastic check, the correlation study);
  /// the other studies keep bases of their own, shifted with it (study_seed).
  std::uint64_t base_seed = 1;
  double t_end_in_tau0 = 4.0;
  // Fig. 3: ε = 0.93, n = 0.05 up to ln t = 8.
  double fig3_restitution = 0.93;
  double fig3_density = 0.05;
  double fig3_t_end = 3000.0;
  // The elastic check counts collisions over the second half of each run (analysis.hpp): to
  // t = 800, 8 runs at N = 5000 give ω/ω_E to ±0.0005–0.001 (standard errors over the runs).
  double elastic_t_end = 800.0;
  WindowRule window{};

  /// A study's base seed: its own default, shifted by base_seed − 1 (modulo 2^64), so that the
  /// default base seed 1 leaves every study as it was and another one re-seeds them all.
  std::uint64_t study_seed(std::uint64_t default_base) const {
    return default_base + (base_seed - 1);
  }

  /// The paper's scale, or the one-minute first look (N = 1000, 3 restitutions, 3 seeds).
  static ReproduceConfig paper_scale();
  static ReproduceConfig quick_look();
};

/// Where a claim comes from: the paper (its verdict says whether the reproduction confirms it)
/// or the suite itself (a finding beyond the paper).
enum class ClaimSource { paper, suite };

/// One claim with its verdict, the number that decides it, and the comparison rows behind it.
struct Claim {
  ClaimSource source = ClaimSource::paper;
  std::string statement;  ///< one line, e.g. "the mu2 coefficient of b is -63/40"
  std::string verdict;    ///< "reproduced", "contradicted", "not reproduced", "beyond the paper"
  std::string deciding;   ///< the number that decides it, with its error
  std::vector<ComparisonRow> rows;
};

struct ReproduceResults {
  ReproduceConfig config;
  std::string version;
  EnsembleSpec fig4_spec, fig3_spec, elastic_spec, dsmc_spec;
  std::vector<PointResult> fig4_points;     ///< all densities × restitutions × modes
  std::vector<PointResult> dsmc_points;     ///< DSMC (molecular chaos) at the Fig. 4 points
  std::vector<PointResult> elastic_points;  ///< ε = 1, every mode and density
  std::vector<PointResult> fig3_points;     ///< ε = 0.93, n = 0.05, modes none, paper, flux
  PointResult fig3_original;                ///< fig3_points[0]: no shuffle
  std::vector<RunOutcome> fig3_runs;        ///< the runs behind Fig. 3's curves
  theory::ExpansionTable coefficients;      ///< μ2 expansion, d = 2, printed dyad
  CorrelationStudy correlations;            ///< the two-particle distribution (runs of its own)
  std::vector<BreakdownRow> breakdown;      ///< linear hydrodynamics against the runs (paper scale)
  std::vector<StructureFactorCurve> breakdown_curves;  ///< S⊥(k, τ) behind `breakdown`
  std::vector<BreakdownRow> breakdown_3d;  ///< the same in d = 3 (BreakdownSpec::three_dimensional)
  std::vector<StructureFactorCurve> breakdown_curves_3d;  ///< S⊥(k, τ) behind `breakdown_3d`
  std::vector<FlowEnergyPoint> flow_energy;  ///< flow's share of T, t ≤ 4τ0 (paper scale)
  GasFieldStudy gas_fields;  ///< original and randomized gases through the break-down (paper scale)
  std::vector<Claim> claims;  ///< the paper's claims first, then the suite's
  Fig3Data fig3;
  Fig4Data fig4;
  BData b;
  A2Data a2;  ///< a2(ε) of every gas against the Sonine theory
  SnapshotData snapshot;
  double seconds = 0.0;
  int failed_runs = 0;
  std::vector<std::string> failures;
};

/// Number of claims whose verdict is "not reproduced" or "contradicted".
int count_not_reproduced(const ReproduceResults& results);

/// Writes breakdown_linear_hydrodynamics.csv, breakdown_structure_factors.csv,
/// breakdown_gases.csv and flow_energy_share.csv into `directory` (nothing when the break-down
/// studies did not run).
void write_breakdown_tables(const ReproduceResults& results, const std::string& directory);

/// Writes haff_estimators.csv (the τ0 estimators compared on the Fig. 4 runs) into `directory`.
void write_estimator_table(const ReproduceResults& results, const std::string& directory);

/// Runs (or loads from the cache) everything and analyses it.
ReproduceResults reproduce(const ReproduceConfig& config, const SweepOptions& sweep);

}  // namespace molchaos::validation
