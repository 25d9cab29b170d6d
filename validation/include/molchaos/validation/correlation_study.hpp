// The correlation study: why the two routes to the paper's b (cooling rate, contact statistics)
// disagree. Runs the original gas and the two molecular-chaos references (the flux-shuffled MD
// gas; DSMC, contact moments only) at the paper's state points (and a compact 3D set) through the sweep machinery and tabulates contact moments, pair
// correlation functions, the cooling rate taken apart, the ansatz's fits and the b verdict.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "molchaos/validation/correlation_tables.hpp"
#include "molchaos/validation/hcs_window.hpp"
#include "molchaos/validation/sweep.hpp"

namespace molchaos::validation {

struct CorrelationStudyConfig {
  std::int64_t particles = 5000;
  std::vector<double> densities{0.05, 0.1};
  /// Fig. 4's grid; with the same seeds these are reproduce()'s runs (shared through the cache).
  std::vector<double> restitutions{0.80, 0.82, 0.84, 0.86, 0.88, 0.90, 0.92, 0.94, 0.96, 0.98};
  int contact_seeds = 8;
  /// Pair correlations (new runs with snapshots): restitutions, seeds, snapshot times in τ0.
  std::vector<double> snapshot_restitutions{0.8, 0.9};
  int snapshot_seeds = 4;
  std::vector<double> snapshot_times_in_tau0{0.3, 1.0, 3.0};
  /// The compact 3D set (spheres): contact moments and pair correlations.
  double density_3d = 0.1;
  std::vector<double> restitutions_3d{0.8, 0.9};
  int seeds_3d = 8;
  /// DSMC, molecular chaos by construction, at every contact point of d = 2 and d = 3: the
  /// second reference beside the flux gas. Four times the MD's seeds, as reproduce() runs them
  /// (shared through the cache); a DSMC run costs a small fraction of an MD run.
  int dsmc_seeds = 32;
  std::uint64_t base_seed = 1;
  WindowRule window{};

  static CorrelationStudyConfig paper_scale() { return {}; }
  /// N = 1000, two restitutions, 4 seeds: seconds, for tests and a first look.
  static CorrelationStudyConfig quick_look();
};

struct CorrelationStudy {
  std::vector<ContactMomentRow> contact_moments;
  std::vector<PairCorrelationRow> pair_correlations;
  std::vector<ImpactParameterRow> impact_parameter;  ///< per gas, point and bin of s
  std::vector<CoolingDecompositionRow> decomposition;
  std::vector<AnsatzFitRow> ansatz;
  BRoutesVerdict b_routes;         ///< printed ansatz: b_cooling against b_contact
  BRoutesVerdict beta_par_routes;  ///< two amplitudes: β∥ from cooling against ⟨(c1·e)(c2·e)⟩
  double two_amplitude_chi2 = 0.0;  ///< the two amplitudes fitted to all four contact moments
  int two_amplitude_dof = 0;
  std::vector<StudyClaim> claims;  ///< claim, verdict, deciding number
  int failed_runs = 0;
  double seconds = 0.0;
  CorrelationStudyConfig config;  ///< what ran (the tables' headers)
  std::string version;            ///< code version (SweepOptions::version), in the tables' headers
};

/// Runs (or loads from the cache) everything the study needs and analyses it.
CorrelationStudy run_correlation_study(const CorrelationStudyConfig& config,
                                       const SweepOptions& sweep);

/// The tables as CSV text: '#' lines (what ran, the code version), the column names, then one
/// row per record. ansatz_fits_csv: per state point, the shifts at contact, the ansatz's fits
/// and the paired routes to b and β∥ behind the report's global tests of them;
/// cooling_decomposition_csv: per state point, the cooling rate's ratio taken apart.
std::string contact_moments_csv(const CorrelationStudy& study);
std::string ansatz_fits_csv(const CorrelationStudy& study);
std::string cooling_decomposition_csv(const CorrelationStudy& study);
std::string pair_correlations_csv(const CorrelationStudy& study);

/// Writes directory/contact_moments.csv, ansatz_fits.csv, cooling_decomposition.csv,
/// pair_correlations.csv and impact_parameter.csv
/// atomically, each with `rerun_lines` (the '#' lines of the options that re-run it) after its
/// title line.
void write_correlation_tables(const CorrelationStudy& study, const std::string& directory,
                              const std::string& rerun_lines);

}  // namespace molchaos::validation
