// Sweep expansion, summaries against theory, summary CSV.
#include "molchaos/validation/ensemble.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/dimension.hpp"

namespace molchaos::validation {
namespace {
constexpr double k_not_applicable = std::numeric_limits<double>::quiet_NaN();
}  // namespace

void validate(const EnsembleSpec& s) {
  if (s.densities.empty()) throw std::invalid_argument("densities: at least one is required");
  if (s.restitutions.empty()) throw std::invalid_argument("restitutions: at least one is required");
  if (s.modes.empty()) throw std::invalid_argument("modes: at least one is required");
  if (s.methods.empty()) throw std::invalid_argument("methods: at least one is required");
  const auto kinds = run_kinds(s);
  for (auto mode : s.modes)
    if (std::none_of(kinds.begin(), kinds.end(), [&](const RunKind& k) { return k.mode == mode; }))
      throw std::invalid_argument(fmt::format(
          "modes: value {} is run by none of the listed methods (method = dsmc runs mode none "
          "only: a shuffle only permutes velocities, which leaves the DSMC state unchanged); "
          "allowed with method = dsmc alone: none",
          sim::to_string(mode)));
  for (auto method : s.methods)
    if (std::none_of(kinds.begin(), kinds.end(),
                     [&](const RunKind& k) { return k.method == method; }))
      throw std::invalid_argument(
          fmt::format("methods: value {} runs mode none only, which is not among the listed modes; "
                      "add none to them",
                      method_name(method)));
  if (s.relax_collisions_per_particle != 0 &&
      std::none_of(s.methods.begin(), s.methods.end(), sim::method_relaxes))
    throw std::invalid_argument(fmt::format(
        "relax_collisions_per_particle: value {} is not allowed when no listed method relaxes "
        "(method = dsmc starts from the homogeneous Maxwellian state; relaxation applies to "
        "method = edmd only); allowed value 0",
        s.relax_collisions_per_particle));
  if (s.seeds < 1 || s.seeds > 100000)
    throw std::invalid_argument("seeds: value " + std::to_string(s.seeds) +
                                " is outside the allowed range [1, 100000]");
  if (!(s.t_end_in_tau0 > 0.0 && s.t_end_in_tau0 <= 1e6))
    throw std::invalid_argument("t_end_in_tau0: must lie in (0, 1e6]");
  if (!(s.t_end_elastic > 0.0)) throw std::invalid_argument("t_end_elastic: must be > 0");
  for (const auto& p : expand(s)) sim::validate(p);
}

double theory_tau0(int dimension, double density, double restitution) {
  if (restitution >= 1.0) return std::numeric_limits<double>::infinity();
  theory::CoolingInputs in;
  in.dimension = dimension;
  in.density = density;
  in.restitution = restitution;
  in.quadrature.relative_tolerance = 1e-8;
  return theory::predict_cooling(in).tau0.value;
}

std::string method_name(sim::Method method) {
  return std::string(sim::find_parameter("method")->choices[static_cast<std::size_t>(method)]);
}

std::string gas_name(const std::string& mode) {
  if (mode == "none") return "original gas";
  if (mode == "paper") return "paper-shuffled gas";
  if (mode == "dsmc") return "DSMC gas";
  return "flux-shuffled gas";
}

std::vector<RunKind> run_kinds(const EnsembleSpec& spec) {
  std::vector<RunKind> kinds;
  for (auto method : spec.methods)
    for (auto mode : spec.modes)
      if (sim::method_runs_mode(method, mode)) kinds.push_back({method, mode});
  return kinds;
}

namespace {
// A DSMC seed of its own for each density (expand): from the density's bits, so that a density
// gets the same seeds whichever other densities a sweep lists (and its cache entries stay valid).
std::uint64_t dsmc_seed(std::uint64_t base_seed, double density, std::uint64_t index) {
  return derive_seed(derive_seed(base_seed, std::bit_cast<std::uint64_t>(density)), index);
}
}  // namespace

std::vector<sim::Parameters> expand(const EnsembleSpec& s) {
  std::vector<sim::Parameters> runs;
  for (double n : s.densities)
    for (double eps : s.restitutions) {
      const double t_end = eps >= 1.0 ? s.t_end_elastic
                           : s.t_end_fixed > 0.0
                               ? s.t_end_fixed
                               : s.t_end_in_tau0 * theory_tau0(s.dimension, n, eps);
      for (const RunKind& kind : run_kinds(s))
        for (int i = 0; i < s.seeds; ++i) {
          sim::Parameters p;
          p.dimension = s.dimension;
          p.particles = s.particles;
          p.density = n;
          p.restitution = eps;
          p.randomize = kind.mode;
          p.seed = kind.method == sim::Method::dsmc
                       ? dsmc_seed(s.base_seed, n, static_cast<std::uint64_t>(i))
                       : derive_seed(s.base_seed, static_cast<std::uint64_t>(i));
          p.t_end = t_end;
          p.samples_per_decade = s.samples_per_decade;
          p.contact_statistics = s.contact_statistics;
          p.method = kind.method;
          // The spec's relaxation is its EDMD runs'; a DSMC run records the none it does.
          p.relax_collisions_per_particle = s.relax_collisions_per_particle;
          sim::default_relaxation_for_method(p);
          runs.push_back(p);
        }
    }
  return runs;
}

void default_relaxation_for_methods(EnsembleSpec& spec) {
  if (std::none_of(spec.methods.begin(), spec.methods.end(), sim::method_relaxes))
    spec.relax_collisions_per_particle = 0.0;
}

EnsembleSpec dsmc_twin(const EnsembleSpec& md, int seeds) {
  EnsembleSpec s = md;
  s.methods = {sim::Method::dsmc};
  s.modes = {sim::Randomization::none};
  s.seeds = seeds;
  default_relaxation_for_methods(s);
  return s;
}

std::vector<PointResult> summarize(const EnsembleSpec& spec, const std::vector<RunOutcome>& runs,
                                   const WindowRule& rule) {
  std::vector<PointResult> points;
  std::size_t k = 0;
  for (double n : spec.densities)
    for (double eps : spec.restitutions)
      for (const RunKind& kind : run_kinds(spec)) {
        std::vector<const sim::RunResult*> group;
        std::vector<double> ratios;
        int failed_runs = 0;
        std::vector<RunNote> errors;  // a failed run's error names the run
        for (int i = 0; i < spec.seeds; ++i, ++k) {
          if (!runs.at(k).ok) {
            ++failed_runs;
            errors.push_back({runs[k].error, std::nullopt});
            continue;
          }
          // An elastic run without a collision measures no frequency (0 ± 0 from every seed
          // would read as a measurement): it counts as failed, as a cooling run that ends before
          // its transient does.
          if (eps >= 1.0 && runs[k].result.collisions == 0) {
            ++failed_runs;
            errors.push_back({fmt::format("no collision by t_end = {}, so no collision frequency "
                                          "(lengthen the run, --t-end-elastic)",
                                          runs[k].result.parameters.t_end),
                              runs[k].result.parameters.seed});
            continue;
          }
          group.push_back(&runs[k].result);
          if (eps >= 1.0) ratios.push_back(collision_frequency_ratio(runs[k].result));
        }
        PointResult r;
        if (eps < 1.0) {
          r.summary = summarize_point(group, rule);
          theory::CoolingInputs in;
          in.dimension = spec.dimension;
          in.density = n;
          in.restitution = eps;
          in.quadrature.relative_tolerance = 1e-10;
          const auto pred = theory::predict_cooling(in);
          r.A_theory = {pred.A.value, pred.A.error};
        } else {
          r.summary.runs = static_cast<int>(group.size());
          r.collision_ratio = mean_and_standard_error(ratios);
          if (ratios.empty())
            r.collision_ratio = {std::numeric_limits<double>::quiet_NaN(),
                                 std::numeric_limits<double>::quiet_NaN()};
        }
        r.summary.dimension = spec.dimension;
        r.summary.density = n;
        r.summary.restitution = eps;
        r.method = kind.method;
        r.summary.mode = std::string(sim::to_string(kind.mode));
        r.summary.failed += failed_runs;
        for (auto& e : errors) r.summary.notes.push_back(std::move(e));
        points.push_back(std::move(r));
      }
  return points;
}

std::vector<std::string> extrapolated_theory_notes(const EnsembleSpec& spec) {
  std::vector<std::string> notes;
  for (double n : spec.densities) {
    const double eta = theory::packing_fraction(spec.dimension, n);
    if (theory::g2_extrapolated(spec.dimension, eta))
      notes.push_back(fmt::format(
          "A_theory at density {} (packing fraction {:.4g}) extrapolates g2(σ) beyond the "
          "equilibrium fluid, which ends at packing {} for {}",
          n, eta, theory::fluid_limit_packing(spec.dimension),
          spec.dimension == 2 ? "disks" : "spheres"));
  }
  return notes;
}

void write_summary_csv(const EnsembleSpec& s, const std::vector<PointResult>& points,
                       const WindowRule& window, const std::string& version,
                       const std::string& path) {
  sim::write_file_atomically(path, [&](std::ostream& out) {
    out << "# molchaos sweep summary (sigma = m = k_B = 1, T0 = 1)\n";
    out << "# version = " << version << "\n";
    out << fmt::format("# dimension = {}\n# particles = {}\n# seeds = {}\n# base_seed = {}\n",
                       s.dimension, s.particles, s.seeds, s.base_seed);
    // Each run length only where a listed point uses it: `sweep --config summary.csv` refuses a
    // length without its points.
    const auto& eps = s.restitutions;
    if (std::any_of(eps.begin(), eps.end(), [](double e) { return e < 1.0; }))
      out << fmt::format("# t_end_in_tau0 = {}\n", s.t_end_in_tau0);
    if (std::any_of(eps.begin(), eps.end(), [](double e) { return e >= 1.0; }))
      out << fmt::format("# t_end_elastic = {}\n", s.t_end_elastic);
    out << fmt::format("# samples_per_decade = {}\n", s.samples_per_decade);
    out << fmt::format("# relax_collisions_per_particle = {}\n", s.relax_collisions_per_particle);
    out << window_rule_line(window);
    if (s.target_relative_error > 0.0)  // `seeds` was the first stage; the runs column says more
      out << fmt::format("# target_error = {}\n# max_seeds = {}\n", s.target_relative_error,
                         s.max_seeds);
    // The state points and modes as listed, so that `sweep --config summary.csv` repeats the
    // sweep; lists space separated, as --config reads them.
    std::vector<std::string> modes;
    for (auto m : s.modes) modes.emplace_back(sim::to_string(m));
    out << fmt::format("# density = {}\n# restitution = {}\n# randomize = {}\n",
                       fmt::join(s.densities, " "), fmt::join(s.restitutions, " "),
                       fmt::join(modes, " "));
    // Like a run's header: the method line only when it is not the default (edmd alone).
    if (s.methods != std::vector<sim::Method>{sim::Method::edmd}) {
      std::vector<std::string> names;
      for (auto m : s.methods) names.push_back(method_name(m));
      out << "# method = " << fmt::format("{}", fmt::join(names, " ")) << "\n";
    }
    out << "# A, a2, mean_dyad (and collision_ratio at eps = 1) are nan at a point where no run "
           "succeeded (runs = 0, failed = their number); their errors are nan where fewer than 2 "
           "runs succeeded (no standard error)\n";
    out << "# nan also where a column does not apply: A, A_theory, mean_dyad, a2 and the "
           "breakdown time at eps = 1 (no cooling), collision_ratio at eps < 1, the breakdown "
           "time where no run broke down\n";
    for (const auto& note : extrapolated_theory_notes(s)) out << "# note: " << note << "\n";
    out << "density,restitution,method,randomize,A,A_err,runs,failed,A_theory,A_theory_err,"
           "mean_dyad,mean_dyad_err,a2,a2_err,breakdowns,breakdown_time,breakdown_time_err,"
           "collision_ratio,collision_ratio_err\n";
    for (const auto& p : points) {
      const auto& m = p.summary;
      const auto error = [&m](double e) { return error_of_runs(e, m.runs); };
      // A column that does not apply to the point holds nan, not the 0 of an unset value, which
      // would read as a measurement.
      const bool cooling = m.restitution < 1.0;
      const auto when = [](bool applies, double v) { return applies ? v : k_not_applicable; };
      const bool broke_down = cooling && m.breakdowns > 0;
      out << fmt::format(
          "{},{},{},{},{:.10g},{:.4g},{},{},{:.10g},{:.3g},{:.8g},{:.3g},{:.6g},{:.3g},{},{:.6g},"
          "{:.3g},{:.8g},{:.3g}\n",
          m.density, m.restitution, method_name(p.method), m.mode, when(cooling, m.A.value),
          when(cooling, error(m.A.error)), m.runs, m.failed, when(cooling, p.A_theory.value),
          when(cooling, p.A_theory.error), when(cooling, m.mean_dyad.value),
          when(cooling, error(m.mean_dyad.error)), when(cooling, m.a2.value),
          when(cooling, error(m.a2.error)), m.breakdowns, when(broke_down, m.breakdown_time.value),
          when(broke_down, error_of_runs(m.breakdown_time.error, m.breakdowns)),
          when(!cooling, p.collision_ratio.value), when(!cooling, error(p.collision_ratio.error)));
    }
  });
}

}  // namespace molchaos::validation
