// The steps of the reproduction (private to validation/): one function per figure and one per
// claim, listed in reproduce.cpp. A figure step fills its data in ReproduceResults; a claim step
// reads the results (runs, figures' data, theory) and returns the claim with its verdict.
#pragma once

#include <string>
#include <vector>

#include "molchaos/sim/parameters.hpp"
#include "molchaos/validation/reproduce.hpp"

namespace molchaos::validation::steps {

// Randomization modes of every ensemble, in this order (original gas first).
inline const std::vector<sim::Randomization> k_modes{
    sim::Randomization::none, sim::Randomization::paper, sim::Randomization::flux};

/// DSMC seeds per Fig. 4 point, as a multiple of the MD's.
inline constexpr int k_dsmc_seed_factor = 4;

/// The rule column of a per-point row that informs a claim decided by one global test.
inline constexpr const char* k_information_rule =
    "per point for information; the claim's χ² decides";

/// Legend text of a mode ("none", "paper", "flux").
std::string mode_label(const std::string& mode);

/// The Fig. 4 ensemble's point at (density, restitution, mode); throws if absent.
const PointResult& find_point(const ReproduceResults& results, double density, double restitution,
                              const std::string& mode);

/// The DSMC ensemble's point at (density, restitution); throws if absent.
const PointResult& find_dsmc_point(const ReproduceResults& results, double density,
                                   double restitution);

/// The suite's coefficients of μ2/μ2(0,0) at a2, b = 0 (its A up to ω0), and ∂/∂b.
double mu2_ratio_at_b0(const theory::ExpansionTable& table, double a2);
double mu2_ratio_b_slope(const theory::ExpansionTable& table, double a2);

// --- figures ------------------------------------------------------------------------------
void figure_fig4(ReproduceResults& results);
void figure_b(ReproduceResults& results);
void figure_a2(ReproduceResults& results);
void figure_fig3(ReproduceResults& results);
void figure_snapshot(ReproduceResults& results);

// --- the paper's claims -----------------------------------------------------------------------
Claim claim_mu2_coefficient_a2(const ReproduceResults& results);
Claim claim_mu2_coefficient_b(const ReproduceResults& results);
Claim claim_prefactors(const ReproduceResults& results);
Claim claim_A_varies_little(const ReproduceResults& results);
Claim claim_randomized_follows_haff(const ReproduceResults& results);
Claim claim_randomized_haff_form(const ReproduceResults& results);
Claim claim_randomized_A_flat(const ReproduceResults& results);
Claim claim_original_A_depends_on_eps(const ReproduceResults& results);
Claim claim_clustering_onset(const ReproduceResults& results);

// --- the suite's own findings -------------------------------------------------------------------
Claim finding_elastic_limit(const ReproduceResults& results);
Claim finding_flux_follows_haff(const ReproduceResults& results);
Claim finding_b_two_ways(const ReproduceResults& results);
Claim finding_flux_equals_dsmc(const ReproduceResults& results);
Claim finding_paper_shuffle_against_dsmc(const ReproduceResults& results);
Claim finding_dsmc_a2_against_sonine(const ReproduceResults& results);
Claim finding_higher_order_coefficients(const ReproduceResults& results);
Claim finding_two_particle_distribution(const ReproduceResults& results);
Claim finding_breakdown_prediction(const ReproduceResults& results);
Claim finding_breakdown_prediction_3d(const ReproduceResults& results);

// --- the precision of the Fig. 4 ensembles (reproduce_precision.cpp) ---------------------------
/// Largest SE(A)/A over the Fig. 4 points (MD and DSMC) with at least two runs.
double largest_relative_error_of_A(const ReproduceResults& results);
Claim finding_estimator_precision(const ReproduceResults& results);

// --- studies with runs of their own (reproduce_studies.cpp) -----------------------------------
/// Runs the correlation study (and, at paper scale, the break-down study) into `results`.
void run_studies(ReproduceResults& results, const SweepOptions& sweep);

// --- the break-down of the homogeneous cooling state (reproduce_breakdown.cpp) ---------------
/// At paper scale: the break-down study and the three gases side by side, into `results`.
void run_breakdown_studies(ReproduceResults& results);
/// The break-down study (d = 2 or 3) and the flow-energy study as the reproduction runs them:
/// their own settings, their base seeds shifted with the reproduction's (study_seed).
BreakdownSpec breakdown_spec(const ReproduceConfig& cfg, int dimension);
FlowEnergySpec flow_energy_spec(const ReproduceConfig& cfg);
Claim claim_shuffles_suppress_vortices(const ReproduceResults& results);
Claim claim_randomized_stays_homogeneous(const ReproduceResults& results);
Claim finding_onset_from_linear_theory(const ReproduceResults& results);
Claim finding_flow_energy_share(const ReproduceResults& results);

}  // namespace molchaos::validation::steps
