// The reproduction as a list of steps: one sweep for every ensemble, the theory's coefficient
// table, then one function per figure and one per claim (reproduce_figures.cpp,
// reproduce_claims.cpp; declared in reproduce_steps.hpp).
//
// Adding a claim of the paper (or a finding of the suite):
//   1. write `Claim claim_<name>(const ReproduceResults& r)` in reproduce_claims.cpp (declare it in
//      reproduce_steps.hpp): read the runs, figure data and theory from `r`, build its comparison
//      rows, and decide every verdict with agreement() / significantly_below() (verdict.hpp, the
//      suite's one rule; put agreement_rule_text() in each row's `rule`);
//   2. add one line `claim_<name>,` to k_claims below (paper's claims before the suite's).
// The report lists it in its summary and its rows in the verdict table without further changes.
// A claim that needs runs of its own adds an EnsembleSpec to run_ensembles() and a field to
// ReproduceResults; a new figure is a `figure_<name>(ReproduceResults&)` in k_figures plus a
// render call in app/cmd_reproduce.cpp.
#include "molchaos/validation/reproduce.hpp"

#include <chrono>
#include <stdexcept>

#include "molchaos/theory/paper_checks.hpp"
#include "molchaos/validation/staged_ensemble.hpp"
#include "reproduce_steps.hpp"

namespace molchaos::validation {

ReproduceConfig ReproduceConfig::paper_scale() { return {}; }

ReproduceConfig ReproduceConfig::quick_look() {
  ReproduceConfig c;
  c.quick = true;
  c.particles = 1000;
  c.restitutions = {0.80, 0.90, 0.96};
  c.seeds = 3;
  c.target_relative_error = 0.0;  // no second stage: a first look, not the paper's precision
  c.fig3_t_end = 1500.0;
  c.elastic_t_end = 100.0;
  return c;
}

namespace steps {

std::string mode_label(const std::string& mode) {
  if (mode == "none") return "original gas (no shuffle)";
  if (mode == "paper") return "randomized: paper's shuffle";
  if (mode == "dsmc") return "DSMC (molecular chaos by construction)";
  return "randomized: flux-weighted shuffle";
}

const PointResult& find_point(const ReproduceResults& r, double density, double restitution,
                              const std::string& mode) {
  for (const auto& p : r.fig4_points)
    if (p.summary.density == density && p.summary.restitution == restitution &&
        p.summary.mode == mode)
      return p;
  throw std::logic_error("reproduce: no Fig. 4 point at the requested state");
}

const PointResult& find_dsmc_point(const ReproduceResults& r, double density, double restitution) {
  for (const auto& p : r.dsmc_points)
    if (p.summary.density == density && p.summary.restitution == restitution) return p;
  throw std::logic_error("reproduce: no DSMC point at the requested state");
}

double mu2_ratio_at_b0(const theory::ExpansionTable& c, double a2) {
  return 1.0 + c.term("a2").coefficient.value * a2 + c.term("a2^2").coefficient.value * a2 * a2;
}

double mu2_ratio_b_slope(const theory::ExpansionTable& c, double a2) {
  return c.term("b").coefficient.value + c.term("a2*b").coefficient.value * a2 +
         c.term("a2^2*b").coefficient.value * a2 * a2;
}

}  // namespace steps

namespace {

using FigureStep = void (*)(ReproduceResults&);
using ClaimStep = Claim (*)(const ReproduceResults&);

// Figures first: several claims read their data (fits, b(ε), the onset).
constexpr FigureStep k_figures[] = {steps::figure_fig4, steps::figure_b, steps::figure_a2,
                                    steps::figure_fig3, steps::figure_snapshot};

// The report's summary lists the claims in this order.
constexpr ClaimStep k_claims[] = {
    // the paper's claims
    steps::claim_mu2_coefficient_a2,
    steps::claim_mu2_coefficient_b,
    steps::claim_prefactors,
    steps::claim_A_varies_little,
    steps::claim_randomized_follows_haff,
    steps::claim_randomized_A_flat,
    steps::claim_original_A_depends_on_eps,
    steps::claim_clustering_onset,
    steps::claim_shuffles_suppress_vortices,
    steps::claim_randomized_stays_homogeneous,
    steps::claim_randomized_haff_form,
    // the suite's own findings
    steps::finding_elastic_limit,
    steps::finding_flux_follows_haff,
    steps::finding_flux_equals_dsmc,
    steps::finding_paper_shuffle_against_dsmc,
    steps::finding_dsmc_a2_against_sonine,
    steps::finding_b_two_ways,
    steps::finding_higher_order_coefficients,
    steps::finding_two_particle_distribution,
    steps::finding_breakdown_prediction,
    steps::finding_breakdown_prediction_3d,
    steps::finding_onset_from_linear_theory,
    steps::finding_flow_energy_share,
    steps::finding_estimator_precision,
};

void record_failures(ReproduceResults& R, const std::vector<RunOutcome>& outcomes) {
  for (const auto& o : outcomes)
    if (!o.ok) {
      ++R.failed_runs;
      R.failures.push_back(o.error);
    }
}

void define_ensembles(ReproduceResults& R, const ReproduceConfig& cfg) {
  EnsembleSpec base;
  base.dimension = 2;
  base.particles = cfg.particles;
  base.seeds = cfg.seeds;
  base.base_seed = cfg.base_seed;
  base.modes = steps::k_modes;
  base.contact_statistics = true;
  R.fig4_spec = base;
  R.fig4_spec.densities = cfg.densities;
  R.fig4_spec.restitutions = cfg.restitutions;
  R.fig4_spec.t_end_in_tau0 = cfg.t_end_in_tau0;
  R.fig4_spec.target_relative_error = cfg.target_relative_error;  // and the DSMC twin's
  R.fig4_spec.max_seeds = cfg.max_seeds;
  R.fig3_spec = base;
  R.fig3_spec.densities = {cfg.fig3_density};
  R.fig3_spec.restitutions = {cfg.fig3_restitution};
  R.fig3_spec.t_end_fixed = cfg.fig3_t_end;
  R.elastic_spec = base;
  R.elastic_spec.densities = cfg.densities;
  R.elastic_spec.restitutions = {1.0};
  R.elastic_spec.t_end_elastic = cfg.elastic_t_end;
  R.elastic_spec.contact_statistics = false;
  // DSMC runs cost milliseconds: several times the MD's seeds buy error bars several times
  // smaller, so that a difference between the flux gas and DSMC is the MD's to explain.
  R.dsmc_spec = dsmc_twin(R.fig4_spec, steps::k_dsmc_seed_factor * cfg.seeds);
}

// One sweep for all three ensembles (one load-balanced pool), then the summaries per point.
void run_ensembles(ReproduceResults& R, const ReproduceConfig& cfg, const SweepOptions& sweep) {
  define_ensembles(R, cfg);
  std::vector<sim::Parameters> all;
  const auto p4 = expand(R.fig4_spec), p3 = expand(R.fig3_spec), pe = expand(R.elastic_spec);
  const auto pd = expand(R.dsmc_spec);
  all.insert(all.end(), p4.begin(), p4.end());
  all.insert(all.end(), p3.begin(), p3.end());
  all.insert(all.end(), pe.begin(), pe.end());
  all.insert(all.end(), pd.begin(), pd.end());
  const auto outcomes = run_sweep(all, sweep);
  record_failures(R, outcomes);
  const auto n4 = static_cast<std::ptrdiff_t>(p4.size());
  const auto n3 = static_cast<std::ptrdiff_t>(p3.size());
  const std::vector<RunOutcome> o4(outcomes.begin(), outcomes.begin() + n4);
  R.fig3_runs.assign(outcomes.begin() + n4, outcomes.begin() + n4 + n3);
  const auto ne = static_cast<std::ptrdiff_t>(pe.size());
  const std::vector<RunOutcome> oe(outcomes.begin() + n4 + n3, outcomes.begin() + n4 + n3 + ne);
  const std::vector<RunOutcome> od(outcomes.begin() + n4 + n3 + ne, outcomes.end());
  R.fig4_points = summarize(R.fig4_spec, o4, cfg.window);
  R.dsmc_points = summarize(R.dsmc_spec, od, cfg.window);
  // Further stages: each (state point, mode) of Fig. 4, MD and DSMC, gets the seeds its target
  // relative SE of A needs (staged_ensemble.hpp; seed_sizing.hpp for why a point is not sized from
  // its own scatter alone). Seeds 0..n−1 come from the cache. Modes are sized apart: A of two
  // modes started from the same relaxed state correlate weakly over seeds (r ≈ 0.2 for the
  // original and the flux gas, measured in the precision finding), so pairing would shrink the
  // variance of their difference by that fraction at most, while equal seeds would give every mode
  // the seeds of its noisiest one.
  record_failures(
      R, grow_to_target({{&R.fig4_points, &R.fig4_spec}, {&R.dsmc_points, &R.dsmc_spec}}, sweep,
                        cfg.window));
  R.fig3_points = summarize(R.fig3_spec, R.fig3_runs, cfg.window);
  R.elastic_points = summarize(R.elastic_spec, oe, cfg.window);
  R.fig3_original = R.fig3_points.at(0);
}

}  // namespace

int count_not_reproduced(const ReproduceResults& results) {
  int n = 0;
  for (const auto& c : results.claims)
    if (c.verdict == "not reproduced" || c.verdict == "contradicted") ++n;
  return n;
}

ReproduceResults reproduce(const ReproduceConfig& cfg, const SweepOptions& sweep) {
  const auto start = std::chrono::steady_clock::now();
  ReproduceResults R;
  R.config = cfg;
  R.version = sweep.version;
  run_ensembles(R, cfg, sweep);
  theory::QuadratureOptions quad;
  quad.relative_tolerance = 1e-10;
  R.coefficients = theory::expand_collision_moment(2, 2, 0.5, theory::k_paper_dyad_factor, quad);
  steps::run_studies(R, sweep);
  for (const auto figure : k_figures) figure(R);
  for (const auto claim : k_claims) R.claims.push_back(claim(R));
  R.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return R;
}

}  // namespace molchaos::validation
