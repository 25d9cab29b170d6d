// `molchaos sweep`: an ensemble of independent runs over state points, methods and randomization
// modes, cached and resumable, summarised per point (A ± standard error against kinetic theory).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>

#include "cli_support.hpp"
#include "commands.hpp"
#include "config_file.hpp"
#include "interrupt_signals.hpp"
#include "molchaos/sim/parameters.hpp"
#include "molchaos/validation/ensemble.hpp"
#include "molchaos/validation/pair_correlations.hpp"
#include "molchaos/validation/staged_ensemble.hpp"
#include "molchaos/version.hpp"
#include "parameter_options.hpp"
#include "sweep_runner.hpp"

namespace molchaos::app {
namespace {

struct SweepCliOptions {
  validation::EnsembleSpec spec;
  std::vector<std::string> modes{"none"};
  std::vector<std::string> methods{"edmd"};
  std::string cache = "results/cache";
  std::string out;
  int threads = 0;
  bool quiet = false;
  bool relax_given = false;  // --relax on the command line or in the --config file
  bool max_seeds_given = false;
  bool t_end_tau0_given = false, t_end_elastic_given = false, target_error_given = false;
  bool threads_given = false;
  std::string config;  // the --config file read (empty: none), which --out may not replace
  const CLI::Option* relax = nullptr;  // --relax, whose value may come from the --config file
};

// Options that apply only to cooling (restitution < 1) or only to elastic (restitution 1) points
// are refused when no listed point is of that kind: they would be dropped without a word.
void reject_options_without_their_points(const SweepCliOptions& o) {
  const auto& eps = o.spec.restitutions;
  const bool cooling = std::any_of(eps.begin(), eps.end(), [](double e) { return e < 1.0; });
  const bool elastic = std::any_of(eps.begin(), eps.end(), [](double e) { return e >= 1.0; });
  if (o.t_end_tau0_given && !cooling)
    throw UsageError("--t-end-tau0",
                     "sets the length of cooling runs (--restitution below 1), "
                     "and none is listed; use --t-end-elastic");
  if (o.target_error_given && !cooling)
    throw UsageError("--target-error",
                     "bounds SE(A)/A, which only cooling runs (--restitution "
                     "below 1) measure, and none is listed");
  if (o.t_end_elastic_given && !elastic)
    throw UsageError("--t-end-elastic",
                     "sets the length of elastic runs (--restitution 1), and "
                     "none is listed; use --t-end-tau0");
}

// Why runs of a point gave no value, one line per reason: many seeds that share a reason say it
// once.
void print_notes(const validation::PointSummary& s) {
  for (const auto& line : validation::note_lines(s.notes)) std::cerr << "  note: " << line << '\n';
}

void run_sweep_command(SweepCliOptions& o) {
  o.spec.modes.clear();
  for (const auto& m : o.modes) {
    o.spec.modes.push_back(*sim::parse_randomization(m));  // checked by the option
  }
  o.spec.methods.clear();
  const sim::ParameterInfo& method_row = *sim::find_parameter("method");
  for (const auto& m : o.methods)  // checked by the option
    o.spec.methods.push_back(static_cast<sim::Method>(*sim::find_choice(method_row, m)));
  // The default relaxation is EDMD's: a sweep none of whose methods relaxes records none. A 0
  // from a --config file of a method that does not relax (a DSMC result) is no choice of the
  // user's: the relaxing runs take the default, as simulate's do.
  if (!o.relax_given) {
    validation::default_relaxation_for_methods(o.spec);
  } else if (o.relax != nullptr) {
    std::string relaxing;
    for (std::size_t k = 0; k < o.methods.size(); ++k)  // o.spec.methods: the same, parsed
      if (sim::method_relaxes(o.spec.methods[k]))
        relaxing += (relaxing.empty() ? "" : ", ") + upper_case(o.methods[k]);
    take_default_over_forced_relaxation(o.spec.relax_collisions_per_particle, *o.relax, o.config,
                                        !relaxing.empty(),
                                        "the " + relaxing + " runs of this sweep relax");
  }
  const std::string remedy = "each point once (use --seeds for more runs per point)";
  reject_repeated_values("--density", o.spec.densities, remedy);
  reject_repeated_values("--restitution", o.spec.restitutions, remedy);
  reject_repeated_values("--randomize", o.modes, remedy);
  reject_repeated_values("--method", o.methods, remedy);
  reject_options_without_their_points(o);
  reject_threads_on_ranks(o.threads_given);
  for (double n : o.spec.densities)
    if (n >= sim::close_packing_density(o.spec.dimension))
      throw UsageError("--density",
                       fmt::format("value {} is at or above close packing {} for --dim {}", n,
                                   sim::close_packing_density(o.spec.dimension), o.spec.dimension));
  if (o.max_seeds_given && o.spec.target_relative_error <= 0.0)
    throw UsageError("--max-seeds",
                     "only with --target-error (it bounds the seeds added to reach it)");
  if (o.spec.target_relative_error > 0.0) {
    if (o.cache.empty())
      throw UsageError("--target-error",
                       "needs a cache (each stage reads the runs before it back from it); give "
                       "--cache DIR");
    if (o.spec.max_seeds < o.spec.seeds)
      throw UsageError("--max-seeds",
                       fmt::format("value {} is below --seeds {}", o.spec.max_seeds, o.spec.seeds));
    // The seeds a point needs follow from its scatter, which one run per point does not give.
    if (o.spec.seeds < 2)
      throw UsageError("--seeds",
                       "value 1 with --target-error: the first stage needs 2 runs or "
                       "more per point to measure their scatter");
  }
  require_distinct_files({{"--cache", o.cache}, {"--out", o.out}}, {{"--config", o.config}});
  if (!o.out.empty() && !o.cache.empty()) {
    // A summary written among the cached runs would replace an entry of that name, or be taken
    // for a corrupt one by the next sweep.
    if (resolved_path(o.out).parent_path() == resolved_path(o.cache))
      throw UsageError("--out", "'" + o.out + "' lies in the --cache folder '" + o.cache +
                                    "', whose files are the cached runs; write the summary "
                                    "outside it");
  }
  try {
    validation::validate(o.spec);
  } catch (const std::invalid_argument& e) {
    throw_as_usage_error("sweep", e.what());
  }
  // Only a sweep that will run creates folders: its cache, and the folder of its summary.
  if (!o.out.empty()) {
    require_writable_file("--out", o.out, /*create_parent=*/true);
    require_no_checkpoint_at("--out", o.out);
  }
  if (!o.cache.empty()) require_usable_directory("--cache", o.cache);
  // A signal ends the sweep at once (interrupt_signals.hpp): every finished run is in the cache
  // already, written whole, so the handler only says what is kept.
  interrupt_signals::install(
      o.cache.empty()
          ? std::string("molchaos: sweep interrupted; no run is kept (--cache ''): the same "
                        "command starts again from the first\n")
          : fmt::format("molchaos: sweep interrupted; the cache {} keeps every finished run, and "
                        "the same command continues from them\n",
                        o.cache));
  validation::SweepOptions so;
  so.cache_directory = o.cache;
  so.threads = o.threads;
  so.progress = !o.quiet;
  so.version = k_version;
  so.runner = default_sweep_runner();
  const auto runs = validation::expand(o.spec);
  const auto outcomes = validation::run_sweep(runs, so);
  const validation::WindowRule window{};
  auto points = validation::summarize(o.spec, outcomes, window);
  // --target-error: further seeds in stages (each reads the seeds before it back from the cache);
  // failed runs are counted per point by the summaries below.
  validation::grow_to_target({{&points, &o.spec}}, so, window);
  // p: how often runs of an A that theory got right would differ by this many standard errors
  // or more (Student's t: from a handful of runs the standard error is itself uncertain).
  std::cout << fmt::format("{:>8} {:>6} {:>6} {:>6} {:>12} {:>10} {:>12} {:>9} {:>7} {:>5}\n",
                           "density", "eps", "method", "mode", "A", "A_err", "A_theory", "diff/SE",
                           "p", "runs");
  int failed = 0;
  for (const auto& p : points) {
    const auto& s = p.summary;
    failed += s.failed;
    if (s.restitution >= 1.0) {
      // As for A below: one run has no standard error.
      std::cout << fmt::format(
          "{:>8} {:>6} {:>6} {:>6}  omega/omega_Enskog = {:.5f} ± {}  ({} run{}){}\n", s.density,
          s.restitution, validation::method_name(p.method), s.mode, p.collision_ratio.value,
          s.runs >= 2 ? fmt::format("{:.5f}", p.collision_ratio.error) : "-", s.runs,
          s.runs == 1 ? "" : "s",
          s.runs >= 2   ? ""
          : s.runs == 0 ? "  (not measured: no run succeeded)"
                        : "  (no error bar: fewer than 2 runs)");
      print_notes(s);
      continue;
    }
    // One run has no standard error: say so instead of printing 0 and an absurd diff/SE.
    const double se = std::hypot(s.A.error, p.A_theory.error);
    const bool error_bar = s.runs >= 2 && se > 0;
    const double t = (s.A.value - p.A_theory.value) / se;
    std::cout << fmt::format(
        "{:>8} {:>6} {:>6} {:>6} {:>12.7g} {:>10} {:>12.7g} {:>9} {:>7} {:>5}{}\n", s.density,
        s.restitution, validation::method_name(p.method), s.mode, s.A.value,
        error_bar ? fmt::format("{:.4g}", s.A.error) : "-", p.A_theory.value,
        error_bar ? fmt::format("{:.2f}", t) : "-",
        error_bar ? fmt::format("{:.2g}", validation::student_p_two_sided(t, s.runs - 1)) : "-",
        s.runs,
        error_bar     ? ""
        : s.runs == 0 ? "  (not measured: no run succeeded)"
                      : "  (no error bar: fewer than 2 runs)");
    print_notes(s);
    // A run that left the homogeneous cooling state is fitted up to its break-down only: where
    // runs did, their A measures a cooling that kinetic theory's homogeneous state no longer
    // describes beyond that time, and a diff/SE against A_theory says so only in the CSV.
    if (s.breakdowns > 0)
      std::cerr << fmt::format(
          "  note: {} of the {} runs left the homogeneous cooling state (break-down at t = {:.4g} "
          "on average, before t_end) and are fitted up to it (doc/validation.md, \"The fit window "
          "of A\"){}\n",
          s.breakdowns, s.runs, s.breakdown_time.value,
          s.breakdowns == s.runs ? "; with every run clustering, compare with theory at a "
                                   "smaller N or box"
                                 : "");
    // A_theory is that of N → ∞. A gas of N particles differs from it at order 1/N: zero total
    // momentum leaves (N − 1)d of the N d degrees of freedom that T counts, and the velocity
    // distribution of N particles is not Maxwell's (a2 = O(1/N) even when elastic). Both methods
    // share these (DSMC with the MD's pair rate, dsmc.hpp): at N = 20, 50, 100 and ε = 0.99 the
    // MD lies about 0.2/N below A_theory, DSMC 0.1–0.17/N (doc/benchmarks.md). Said where these
    // runs resolve that measured 0.2/N (1/N alone overstated it five times).
    const double finite_n = 0.2 / static_cast<double>(o.spec.particles);
    if (error_bar && finite_n > s.A.error / std::abs(s.A.value))
      std::cerr << fmt::format(
          "  note: A_theory is that of N → ∞; a gas of N = {} lies about 0.2/N = {:.2g} % below "
          "it (measured, MD; DSMC 0.1–0.2/N: zero total momentum, the velocity distribution of N "
          "particles), more than SE(A)/A = {:.2g} %: compare methods at equal N\n",
          o.spec.particles, 100 * finite_n, 100 * s.A.error / std::abs(s.A.value));
  }
  for (const auto& note : validation::extrapolated_theory_notes(o.spec))
    std::cerr << "note: " << note << '\n';
  if (o.spec.target_relative_error > 0.0) {
    int above = 0;
    for (const auto& p : points)
      if (p.summary.restitution < 1.0 && p.summary.runs >= 2 &&
          p.summary.A.error > o.spec.target_relative_error * std::abs(p.summary.A.value))
        ++above;
    if (above > 0)
      std::cerr << fmt::format(
          "note: SE(A)/A is above --target-error {} at {} point(s): --max-seeds {} or the {} "
          "stages were reached\n",
          o.spec.target_relative_error, above, o.spec.max_seeds, validation::k_target_stages);
  }
  if (!o.out.empty()) {
    const auto parent = std::filesystem::path(o.out).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    validation::write_summary_csv(o.spec, points, window, k_version, o.out);
  }
  if (failed > 0)
    throw std::runtime_error(fmt::format("{} run(s) failed or could not be fitted", failed));
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepCliOptions>();
  CLI::App* cmd =
      app.add_subcommand("sweep", "Ensemble of runs over state points; A ± SE vs theory");
  add_parameter_option(cmd, "dimension", o->spec.dimension);
  add_parameter_option(cmd, "particles", o->spec.particles);
  add_parameter_list_option(cmd, "density", o->spec.densities);
  add_parameter_list_option(cmd, "restitution", o->spec.restitutions);
  add_parameter_list_option(cmd, "randomize", o->modes);
  add_parameter_list_option(cmd, "method", o->methods)
      ->description(
          "Methods (comma separated): edmd (event-driven MD), dsmc (DSMC, velocities only). "
          "Each runs every --randomize mode it can at every state point: edmd all, dsmc only "
          "none (a shuffle leaves DSMC unchanged), so `--method edmd,dsmc --randomize none,flux` "
          "runs DSMC once per state point beside both MD gases. A mode no listed method runs, or "
          "a method that runs no listed mode, is an error.")
      ->default_str("edmd");
  cmd->add_option("--seeds", o->spec.seeds, "independent runs per point")
      ->transform(integer_in(1, 100000))
      ->capture_default_str();
  CLI::Option* target_error =
      cmd->add_option("--target-error", o->spec.target_relative_error,
                      "more seeds, in stages, until SE(A)/A is at most this at every point "
                      "(relative; needs --cache)")
          ->transform(real_in(0.0, false, 1.0, false));
  CLI::Option* max_seeds = cmd->add_option("--max-seeds", o->spec.max_seeds,
                                           "at most this many seeds per point "
                                           "with --target-error")
                               ->transform(integer_in(1, 100000))
                               ->capture_default_str();
  cmd->add_option("--base-seed", o->spec.base_seed, "base seed; run i uses a hash of (base, i)")
      ->transform(unsigned_integer())
      ->capture_default_str();
  CLI::Option* t_end_tau0 =
      cmd->add_option("--t-end-tau0", o->spec.t_end_in_tau0,
                      "run length in kinetic-theory tau0 (restitution below 1)")
          ->transform(real_in(0.0, false, 1e6, true))
          ->capture_default_str();
  CLI::Option* t_end_elastic =
      cmd->add_option("--t-end-elastic", o->spec.t_end_elastic, "run length at restitution 1")
          ->transform(real_in(0.0, false, 1e9, true))
          ->capture_default_str();
  add_parameter_option(cmd, "samples_per_decade", o->spec.samples_per_decade);
  CLI::Option* relax = add_parameter_option(cmd, "relax_collisions_per_particle",
                                            o->spec.relax_collisions_per_particle);
  cmd->add_option("--cache", o->cache, "cache directory ('' for none)")->capture_default_str();
  CLI::Option* threads = cmd->add_option("--threads", o->threads, "worker threads (0: all cores)")
                             ->transform(integer_in(0, 1024))
                             ->capture_default_str();
  cmd->add_option("--out", o->out, "summary CSV")->check(path_name());
  cmd->add_flag("--quiet", o->quiet, "no progress on stderr");
  set_callback_with_config(cmd, [o, relax, max_seeds, target_error, t_end_tau0, t_end_elastic,
                                 threads](const std::string& config) {
    o->config = config;
    o->relax = relax;
    o->relax_given = relax->count() > 0;
    o->max_seeds_given = max_seeds->count() > 0;
    o->target_error_given = target_error->count() > 0;
    o->t_end_tau0_given = t_end_tau0->count() > 0;
    o->t_end_elastic_given = t_end_elastic->count() > 0;
    o->threads_given = threads->count() > 0;
    run_sweep_command(*o);
  });
}

}  // namespace molchaos::app
