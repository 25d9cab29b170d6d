// A parameter sweep as a value: which state points, which randomization modes, how many seeds;
// expanded into run parameters, run, and summarised per state point against kinetic theory.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "molchaos/sim/parameters.hpp"
#include "molchaos/validation/analysis.hpp"
#include "molchaos/validation/sweep.hpp"

namespace molchaos::validation {

struct EnsembleSpec {
  int dimension = 2;
  std::int64_t particles = 5000;
  std::vector<double> densities{0.05};
  std::vector<double> restitutions{0.9};
  std::vector<sim::Randomization> modes{sim::Randomization::none};
  int seeds = 4;
  std::uint64_t base_seed = 1;
  /// Cooling runs last this many kinetic-theory τ0 (T falls to 1/(1 + k)²).
  double t_end_in_tau0 = 4.0;
  /// If > 0, every cooling run lasts exactly this long instead.
  double t_end_fixed = 0.0;
  /// Duration of elastic (ε = 1) runs.
  double t_end_elastic = 200.0;
  int samples_per_decade = 40;
  double relax_collisions_per_particle = 20.0;
  bool contact_statistics = true;
  /// The methods; each runs every listed mode it can (sim::method_runs_mode: DSMC only mode
  /// none, so it runs once per state point beside the MD's shuffles). Every method must run one
  /// listed mode at least, and every mode must be run by one listed method at least.
  std::vector<sim::Method> methods{sim::Method::edmd};
  /// If > 0, the points get more seeds in stages until SE(A)/A is at most this at every one
  /// (staged_ensemble.hpp), up to max_seeds each; `seeds` is then the first stage.
  double target_relative_error = 0.0;
  int max_seeds = 1000;
};

/// One kind of run at every state point: a method with a mode it runs.
struct RunKind {
  sim::Method method = sim::Method::edmd;
  sim::Randomization mode = sim::Randomization::none;
};

/// The kinds of run of a spec at each state point, methods in their listed order and within each
/// its modes in theirs (pairs the method cannot run left out).
std::vector<RunKind> run_kinds(const EnsembleSpec& spec);

/// Throws std::invalid_argument naming the field for an empty or out-of-range spec.
void validate(const EnsembleSpec& spec);

/// The name of a method as the parameter table spells it ("edmd", "dsmc").
std::string method_name(sim::Method method);
/// The gas a row's mode names, as claims print it: "none" original gas, "paper" paper-shuffled
/// gas, "flux" flux-shuffled gas, "dsmc" DSMC gas.
std::string gas_name(const std::string& mode);

/// Kinetic-theory τ0 (T0 = 1, b = 0) used to size the runs; +inf at ε = 1.
double theory_tau0(int dimension, double density, double restitution);

/// All runs, ordered by density, restitution, run kind (run_kinds), seed index. Seed index i uses
/// derive_seed(base_seed, i) at every state point, method and mode (common random numbers: the
/// modes and restitutions at one density start from the same relaxed configurations), except
/// that DSMC runs take seeds of their density (dsmc_seed): DSMC keeps velocities only and the
/// density enters through ω_E alone, so one seed at two densities would be one realisation on
/// two time scales (their A/A_theory correlated at 0.999), counted twice by every χ².
std::vector<sim::Parameters> expand(const EnsembleSpec& spec);

/// The relaxation of a spec whose relax_collisions_per_particle was not given, by the rule of
/// sim::default_relaxation_for_method (sim::method_relaxes): the spec's relaxation is that of its
/// runs that relax, so it is kept while a listed method relaxes and is 0 when none does.
void default_relaxation_for_methods(EnsembleSpec& spec);

/// The DSMC twin of an MD ensemble: the same state points, `seeds` seeds, mode none (the method's
/// only one) and DSMC's relaxation (default_relaxation_for_methods: none).
EnsembleSpec dsmc_twin(const EnsembleSpec& md, int seeds);

struct PointResult {
  PointSummary summary;
  sim::Method method = sim::Method::edmd;
  Measurement A_theory;         ///< b = 0
  Measurement collision_ratio;  ///< ε = 1 only: ω/ω_Enskog, mean ± SE
};

/// Groups outcomes by (density, restitution, method, mode) in the order of expand().
std::vector<PointResult> summarize(const EnsembleSpec& spec, const std::vector<RunOutcome>& runs,
                                   const WindowRule& rule);

/// One line per density of the spec at which kinetic theory's A_theory extrapolates g2(σ) beyond
/// the equilibrium fluid (theory::g2_extrapolated); empty when every density is a fluid's.
std::vector<std::string> extrapolated_theory_notes(const EnsembleSpec& spec);

/// Summary table as CSV (header lines with the spec, the fit window's rule and the version, then
/// one row per point) to a temporary file renamed to path.
void write_summary_csv(const EnsembleSpec& spec, const std::vector<PointResult>& points,
                       const WindowRule& window, const std::string& version,
                       const std::string& path);

}  // namespace molchaos::validation
