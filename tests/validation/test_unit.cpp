// validation/: the Haff fit on exact data, the window rule, straight-line fits, ensemble
// statistics, seeds, and the cache (round trip, corrupt entries recomputed).
#define BOOST_TEST_MODULE validation_unit
#include <unistd.h>

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "molchaos/sim/csv.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/validation/analysis.hpp"
#include "molchaos/validation/ensemble.hpp"
#include "molchaos/validation/estimator_study.hpp"
#include "molchaos/validation/haff_fit.hpp"
#include "molchaos/validation/pair_correlations.hpp"
#include "molchaos/validation/report_html.hpp"
#include "molchaos/validation/sweep.hpp"

using namespace molchaos;
using namespace molchaos::validation;

namespace {
std::vector<sim::Sample> haff_samples(double T0, double tau0, double t_max, int n) {
  std::vector<sim::Sample> out;
  for (int i = 0; i <= n; ++i) {
    sim::Sample s;
    s.t = t_max * std::pow(10.0, -3.0 + 3.0 * i / n);
    s.temperature = theory::haff_temperature(s.t, T0, tau0);
    s.collisions = static_cast<std::uint64_t>(1000 * s.t);
    s.density_mode = 1.0;
    s.velocity_mode = 1.0;
    out.push_back(s);
  }
  return out;
}
}  // namespace

// The sim library keeps its own g2 and Enskog frequency (it does not depend on theory/; DSMC and
// the run's normalisation need them); they must be the theory library's, bit for bit.
BOOST_AUTO_TEST_CASE(sim_and_theory_share_g2_and_enskog_frequency) {
  for (int d : {2, 3})
    for (double n : {1e-6, 0.05, 0.1, 0.4, 0.8}) {
      BOOST_TEST(molchaos::sim::contact_value_g2(d, n) ==
                 molchaos::theory::contact_value_g2_at_density(d, n));
      for (double T : {1e-3, 1.0, 7.5})
        BOOST_TEST(molchaos::sim::enskog_collision_frequency(d, n, T) ==
                   molchaos::theory::enskog_collision_frequency(d, n, T));
    }
}

// A sweep beyond the equilibrium fluid compares with a theory whose g2 is extrapolated: its summary
// says so, once per such density (disks: packing 0.7 at n = 0.891; n = 0.9 is beyond, 0.88 not).
BOOST_AUTO_TEST_CASE(sweep_notes_the_densities_where_theory_extrapolates) {
  EnsembleSpec spec;
  spec.dimension = 2;
  spec.densities = {0.05, 0.88, 0.9, 1.0};
  const auto notes = extrapolated_theory_notes(spec);
  BOOST_TEST_REQUIRE(notes.size() == 2u);
  BOOST_TEST(notes[0].starts_with("A_theory at density 0.9 (packing fraction 0.7069)"));
  BOOST_TEST(notes[1].starts_with("A_theory at density 1 "));
  spec.densities = {0.05, 0.1};
  BOOST_TEST(extrapolated_theory_notes(spec).empty());
}

BOOST_AUTO_TEST_CASE(haff_fit_recovers_exact_parameters) {
  const auto samples = haff_samples(0.97, 123.4, 1000.0, 60);
  const HaffFit f = fit_haff(samples, 1.0, 1000.0);
  BOOST_TEST_REQUIRE(f.ok);
  BOOST_TEST(std::abs(f.T0 - 0.97) <= 1e-9);
  BOOST_TEST(std::abs(f.tau0 - 123.4) <= 1e-7);
  // τ0 referred to T0 = 1: the slope of 1/√T is invariant.
  BOOST_TEST(std::abs(f.tau0_unit - 123.4 * std::sqrt(0.97)) <= 1e-7);
  BOOST_TEST(f.rms_relative_residual <= 1e-10);
}

BOOST_AUTO_TEST_CASE(haff_fit_refuses_too_few_points_and_heating) {
  const auto samples = haff_samples(1.0, 10.0, 100.0, 60);
  BOOST_TEST(!fit_haff(samples, 50.0, 51.0).ok);
  auto heating = samples;
  for (auto& s : heating) s.temperature = 1.0 + s.t;
  BOOST_TEST(!fit_haff(heating, 1.0, 100.0).ok);
}

// Every τ0 estimator is exact on a Haff series, at any T0 (τ0 referred to T0 = 1 is √T0·τ0),
// also when the series stays flat between two samples (a stretch without collisions).
BOOST_AUTO_TEST_CASE(haff_estimators_exact_on_haff_series) {
  auto samples = haff_samples(0.97, 123.4, 1000.0, 60);
  for (HaffEstimator e : k_haff_estimators) {
    const Tau0Estimate r = estimate_tau0(e, samples, 1.0, 1000.0);
    BOOST_TEST_REQUIRE(r.ok, to_string(e));
    BOOST_TEST(std::abs(r.tau0_unit / (123.4 * std::sqrt(0.97)) - 1.0) <= 1e-9, to_string(e));
  }
  // The integrated form weighs each stretch by its √T dt: a flat stretch of the series (T held
  // at its value) raises the integral by exactly √T·Δt.
  const std::size_t k = 40;
  samples.insert(samples.begin() + k + 1, samples[k]);
  const double dt = 0.5 * (samples[k + 2].t - samples[k].t);
  for (std::size_t i = k + 1; i < samples.size(); ++i) samples[i].t += dt;
  const Tau0Estimate flat =
      estimate_tau0(HaffEstimator::integrated, samples, 1.0, samples.back().t);
  BOOST_TEST_REQUIRE(flat.ok);
  const double log_ratio = 0.5 * std::log(samples.front().temperature / samples.back().temperature);
  const double expected =
      123.4 * std::sqrt(0.97) + std::sqrt(samples[k].temperature) * dt / log_ratio;
  BOOST_TEST(std::abs(flat.tau0_unit / expected - 1.0) <= 1e-9);
}

// The estimator comparison on synthetic runs: an estimator that reads every run 1 % high has
// shift +1 % with no error and the same cost; one with twice the spread costs four times as
// many runs. Correlation over seeds: +1 for the same values, −1 for mirrored ones, and only
// seeds both gases have count.
BOOST_AUTO_TEST_CASE(estimator_comparison_and_seed_correlation) {
  PointSummary p, q, mirrored;
  const double values[] = {20.0, 21.0, 19.5, 20.5, 22.0};
  for (std::size_t k = 0; k < std::size(values); ++k) {
    const double v = values[k], spread = v - 20.6;
    p.A_by_estimator.push_back({v, v * 1.01, 20.6 + 2.0 * spread, v});
    p.A_by_seed.emplace_back(k, v);
    q.A_by_seed.emplace_back(k, 3.0 * v + 1.0);
    mirrored.A_by_seed.emplace_back(k, -v);
  }
  q.A_by_seed.emplace_back(99, 1e6);  // a seed p lacks: ignored
  const auto rows = compare_estimator_scatter({&p});
  BOOST_TEST_REQUIRE(rows.size() == k_haff_estimators.size());
  BOOST_TEST(rows[1].shift_from_least_squares.value == 0.01, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(rows[1].shift_from_least_squares.error <= 1e-15);
  BOOST_TEST(rows[1].cost_ratio == 1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(rows[2].cost_ratio == 4.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(rows[0].degrees_of_freedom == 4);
  BOOST_TEST(seed_correlation({&p}, {&q}).value == 1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(seed_correlation({&p}, {&mirrored}).value == -1.0,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(seed_correlation({&p}, {&q}).error == 0.5, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(haff_estimators_refuse_heating_and_short_windows) {
  const auto samples = haff_samples(1.0, 10.0, 100.0, 60);
  auto heating = samples;
  for (auto& s : heating) s.temperature = 1.0 + s.t;
  for (HaffEstimator e : k_haff_estimators) {
    BOOST_TEST(!estimate_tau0(e, samples, 50.0, 51.0).ok, to_string(e));
    BOOST_TEST(!estimate_tau0(e, heating, 1.0, 100.0).ok, to_string(e));
  }
}

BOOST_AUTO_TEST_CASE(window_rule) {
  auto samples = haff_samples(1.0, 50.0, 1000.0, 60);
  WindowRule rule;
  // 3 collisions per particle with N = 1000: 1500 collisions, i.e. t ≥ 1.5.
  FitWindow w = choose_window(samples, 1000, rule);
  BOOST_TEST(w.valid);
  BOOST_TEST(w.t_start >= 1.5);
  BOOST_TEST(!w.breakdown.detected);
  BOOST_TEST(w.t_stop == samples.back().t);
  // A single spike is noise; two consecutive samples above threshold are a break-down.
  samples[40].density_mode = 9.0;
  BOOST_TEST(!detect_breakdown(samples, rule).detected);
  samples[45].velocity_mode = 6.0;
  samples[46].velocity_mode = 6.0;
  const Breakdown b = detect_breakdown(samples, rule);
  BOOST_TEST(b.detected);
  BOOST_TEST(b.time == samples[45].t);
  BOOST_TEST(b.indicator == "velocity_mode");
  BOOST_TEST(choose_window(samples, 1000, rule).t_stop == samples[45].t);
}

BOOST_AUTO_TEST_CASE(straight_line_fit) {
  std::vector<double> x{0.8, 0.85, 0.9, 0.95};
  std::vector<Measurement> y;
  for (double xi : x) y.push_back({2.0 - 3.0 * xi, 0.1});
  const LinearFit f = fit_line(x, y);
  BOOST_TEST(std::abs(f.slope + 3.0) <= 1e-12);
  BOOST_TEST(std::abs(f.intercept - 2.0) <= 1e-12);
  // Exact data: χ² = 0, errors from the weights alone: σ_slope = σ/√Σ(x − x̄)².
  BOOST_TEST(std::abs(f.slope_error - 0.1 / std::sqrt(0.0125)) <= 1e-9);
  BOOST_CHECK_THROW(fit_line({1.0}, {{1.0, 0.1}}), std::invalid_argument);
  // Without errors: the slope error from the scatter about the line, and no χ² (was the mean
  // squared residual, printed as χ²/dof). Residuals +-0.01 alternating about y = 1 + x.
  std::vector<Measurement> bare;
  for (std::size_t k = 0; k < x.size(); ++k)
    bare.push_back({1.0 + x[k] + (k % 2 ? 0.01 : -0.01), 0.0});
  const LinearFit g = fit_line(x, bare);
  BOOST_TEST(std::isnan(g.chi2_per_dof));
  BOOST_TEST(g.slope_error > 0.0);
}

BOOST_AUTO_TEST_CASE(mean_and_standard_error_values) {
  const Measurement m = mean_and_standard_error({1.0, 2.0, 3.0, 4.0});
  BOOST_TEST(m.value == 2.5);
  BOOST_TEST(std::abs(m.error - std::sqrt(5.0 / 3.0 / 4.0)) <= 1e-15);
  BOOST_TEST(mean_and_standard_error({7.0}).error == 0.0);
}

// Student's t in closed form: one degree of freedom is Cauchy's, P(|t| > x) = 1 − (2/π) atan x;
// two give P(|t| > x) = 1 − x/√(x² + 2).
BOOST_AUTO_TEST_CASE(student_two_sided_tail_in_closed_form) {
  namespace tt = boost::test_tools;
  for (const double x : {0.0, 0.5, 1.0, 3.0, 20.0}) {
    BOOST_TEST(student_p_two_sided(x, 1) == 1.0 - 2.0 / M_PI * std::atan(x), tt::tolerance(1e-12));
    BOOST_TEST(student_p_two_sided(-x, 2) == 1.0 - x / std::sqrt(x * x + 2.0),
               tt::tolerance(1e-12));
  }
  BOOST_TEST(student_p_two_sided(4.0, 0) == 1.0);  // one run: no scatter, no test
}

BOOST_AUTO_TEST_CASE(seeds_depend_on_base_and_index_only) {
  std::set<std::uint64_t> seen;
  for (std::uint64_t i = 0; i < 1000; ++i) seen.insert(derive_seed(42, i));
  BOOST_TEST(seen.size() == 1000u);
  BOOST_TEST(derive_seed(42, 7) == derive_seed(42, 7));
  BOOST_TEST(derive_seed(42, 7) != derive_seed(43, 7));
}

BOOST_AUTO_TEST_CASE(cache_round_trip_and_corruption) {
  const auto dir = std::filesystem::temp_directory_path() / "molchaos_cache_test";
  std::filesystem::remove_all(dir);
  sim::Parameters p;
  p.particles = 200;
  p.density = 0.05;
  p.restitution = 0.9;
  p.t_end = 20.0;
  p.relax_collisions_per_particle = 2;
  SweepOptions o;
  o.cache_directory = dir.string();
  o.progress = false;
  o.version = "test";
  const auto first = run_sweep({p}, o);
  BOOST_TEST_REQUIRE(first.at(0).ok);
  BOOST_TEST(!first[0].from_cache);
  const auto second = run_sweep({p}, o);
  BOOST_TEST(second.at(0).from_cache);
  BOOST_TEST(second[0].result.samples.size() == first[0].result.samples.size());
  BOOST_TEST(second[0].result.samples.back().temperature ==
             first[0].result.samples.back().temperature);
  // Another version is another key.
  SweepOptions other = o;
  other.version = "test2";
  BOOST_TEST(cache_key(p, o.version) != cache_key(p, other.version));
  // Truncate the entry: it must be detected and recomputed, identically.
  const auto path = dir / (cache_key(p, o.version) + ".csv");
  const auto size = std::filesystem::file_size(path);
  std::filesystem::resize_file(path, size / 2);
  const auto third = run_sweep({p}, o);
  BOOST_TEST(!third.at(0).from_cache);
  BOOST_TEST(third[0].result.samples.back().temperature ==
             first[0].result.samples.back().temperature);
  BOOST_TEST(std::filesystem::file_size(path) == size);
  // No temporary files are left behind.
  for (const auto& e : std::filesystem::directory_iterator(dir))
    BOOST_TEST(e.path().extension() == ".csv");
  std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(sweep_spec_validation) {
  EnsembleSpec s;
  s.seeds = 0;
  BOOST_CHECK_THROW(validate(s), std::invalid_argument);
  s.seeds = 2;
  s.restitutions = {};
  BOOST_CHECK_THROW(validate(s), std::invalid_argument);
  s.restitutions = {1.5};
  BOOST_CHECK_THROW(validate(s), std::invalid_argument);
}

// Two methods at the same state points: each runs the listed modes it can (DSMC only none), in
// the listed order, the MD modes with the same seeds; a mode or a method left without runs is
// refused.
BOOST_AUTO_TEST_CASE(sweep_over_methods_pairs_each_with_the_modes_it_runs) {
  using sim::Method;
  using sim::Randomization;
  EnsembleSpec s;
  s.particles = 200;
  s.restitutions = {0.8, 0.9};
  s.seeds = 2;
  s.methods = {Method::edmd, Method::dsmc};
  s.modes = {Randomization::none, Randomization::paper, Randomization::flux};
  const auto kinds = run_kinds(s);
  BOOST_TEST_REQUIRE(kinds.size() == 4u);
  BOOST_TEST((kinds[3].method == Method::dsmc && kinds[3].mode == Randomization::none));
  const auto runs = expand(s);
  BOOST_TEST_REQUIRE(runs.size() == 2u * 4u * 2u);
  for (std::size_t k = 0; k < 4; ++k) {  // the first state point: kinds × seeds
    BOOST_TEST((runs[2 * k].method == kinds[k].method));
    BOOST_TEST((runs[2 * k].randomize == kinds[k].mode));
    if (kinds[k].method == Method::edmd) BOOST_TEST(runs[2 * k + 1].seed == runs[1].seed);
  }
  BOOST_CHECK_NO_THROW(validate(s));
  s.methods = {Method::dsmc};
  BOOST_CHECK_EXCEPTION(validate(s), std::invalid_argument, [](const auto& e) {
    return std::string(e.what()).starts_with("modes: value paper");
  });
  s.methods = {Method::edmd, Method::dsmc};
  s.modes = {Randomization::flux};
  BOOST_CHECK_EXCEPTION(validate(s), std::invalid_argument, [](const auto& e) {
    return std::string(e.what()).starts_with("methods: value dsmc");
  });
}

// A spec's relaxation follows sim::default_relaxation_for_method, the one rule: kept while a
// listed method relaxes, none when no listed method does. The DSMC twin of an MD spec with its
// own relaxation takes DSMC's and changes nothing else of the runs.
BOOST_AUTO_TEST_CASE(spec_relaxation_follows_the_rule_for_each_method) {
  using sim::Method;
  auto rule_of = [](Method method, double relax) {
    sim::Parameters run;
    run.method = method;
    run.relax_collisions_per_particle = relax;
    sim::default_relaxation_for_method(run);
    return run.relax_collisions_per_particle;
  };
  EnsembleSpec s;
  s.relax_collisions_per_particle = 7;
  const std::vector<std::vector<Method>> method_lists = {
      {Method::edmd}, {Method::dsmc}, {Method::edmd, Method::dsmc}, {Method::dsmc, Method::edmd}};
  for (const auto& methods : method_lists) {
    EnsembleSpec t = s;
    t.methods = methods;
    default_relaxation_for_methods(t);
    const bool relaxes = std::any_of(methods.begin(), methods.end(), sim::method_relaxes);
    BOOST_TEST(t.relax_collisions_per_particle == (relaxes ? 7.0 : 0.0));
  }
  s.particles = 200;
  s.densities = {0.05, 0.1};
  s.seeds = 3;
  const EnsembleSpec twin = dsmc_twin(s, 2);
  BOOST_TEST(twin.relax_collisions_per_particle == rule_of(Method::dsmc, 7));
  BOOST_CHECK_NO_THROW(validate(twin));
  const auto md_runs = expand(s), twin_runs = expand(twin);
  BOOST_TEST_REQUIRE(twin_runs.size() == 2u * 2u);
  for (std::size_t k = 0; k < twin_runs.size(); ++k) {
    const sim::Parameters& run = twin_runs[k];
    const sim::Parameters& md = md_runs[k / 2 * 3 + k % 2];  // same point, same seed index
    BOOST_TEST((run.method == Method::dsmc && run.randomize == sim::Randomization::none));
    BOOST_TEST(run.relax_collisions_per_particle == rule_of(Method::dsmc, 7));
    BOOST_TEST(run.density == md.density);
    BOOST_TEST(run.t_end == md.t_end);
  }
}

// DSMC at two densities from one seed would be one realisation on two time scales (velocities
// only; n enters through ω_E): each density draws its own seeds, the same whichever other
// densities are listed, and all distinct.
BOOST_AUTO_TEST_CASE(dsmc_seeds_are_the_densitys_own) {
  EnsembleSpec s;
  s.particles = 200;
  s.methods = {sim::Method::dsmc};
  s.restitutions = {0.9};
  s.seeds = 3;
  s.densities = {0.05, 0.1};
  const auto both = expand(s);
  s.densities = {0.1};
  const auto alone = expand(s);
  BOOST_TEST_REQUIRE(both.size() == 6u);
  std::set<std::uint64_t> seeds;
  for (const auto& run : both) seeds.insert(run.seed);
  BOOST_TEST(seeds.size() == 6u);
  for (std::size_t i = 0; i < 3; ++i) BOOST_TEST(alone[i].seed == both[3 + i].seed);
}

// Notes grouped by reason: one line for the runs sharing one, naming how many and the first
// seeds; a lone run's note names its seed; a failed run's error (which names the run) as it is.
BOOST_AUTO_TEST_CASE(run_notes_one_line_per_reason) {
  std::vector<RunNote> notes;
  for (std::uint64_t seed = 11; seed <= 15; ++seed) notes.push_back({"too short", seed});
  notes.push_back({"no collision", 7});
  notes.push_back({"run 3 (seed=9) failed: disk full", std::nullopt});
  const auto lines = note_lines(notes);
  BOOST_TEST_REQUIRE(lines.size() == 3u);
  BOOST_TEST(lines[0] == "5 runs (seeds 11, 12, 13 and 2 more): too short");
  BOOST_TEST(lines[1] == "seed 7: no collision");
  BOOST_TEST(lines[2] == "run 3 (seed=9) failed: disk full");
  BOOST_TEST(note_lines({{"too short", 1}, {"too short", 2}}).at(0) ==
             "2 runs (seeds 1, 2): too short");
  BOOST_TEST(note_lines({}).empty());
}

// Two runs that broke down at the same sample scatter by nothing; their mean is known only to the
// sample grid's rounding, the error's floor (was: an error of 0).
BOOST_AUTO_TEST_CASE(break_down_times_at_one_sample_carry_the_grids_rounding) {
  sim::RunResult run;
  run.parameters.particles = 1000;
  run.parameters.restitution = 0.9;
  run.samples = haff_samples(1.0, 50.0, 1000.0, 60);
  run.samples[45].velocity_mode = run.samples[46].velocity_mode = 6.0;
  const PointSummary s = summarize_point({&run, &run}, WindowRule{});
  BOOST_TEST_REQUIRE(s.breakdowns == 2);
  const double t = run.samples[45].t, width = t - run.samples[44].t;
  BOOST_TEST(s.breakdown_time.value == t);
  BOOST_TEST(s.breakdown_time.error == std::sqrt(2 * width * width / 12) / 2,
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(s.log_breakdown_time.error == std::log(t / run.samples[44].t) / std::sqrt(24.0),
             boost::test_tools::tolerance(1e-14));
}

// A point where no run succeeded has no A: nan (printed as such in every table), not 0.
BOOST_AUTO_TEST_CASE(a_point_without_successful_runs_has_no_value) {
  const PointSummary s = summarize_point({}, WindowRule{});
  BOOST_TEST(s.runs == 0);
  BOOST_TEST(std::isnan(s.A.value));
  BOOST_TEST(std::isnan(s.A.error));
  BOOST_TEST(std::isnan(s.a2.value));
  BOOST_TEST(std::isnan(s.mean_dyad.value));
}

// An elastic run without a collision (t_end shorter than a mean free time) measures no collision
// frequency: the point is not measured (nan) and the run counted as failed, not 0 ± 0.
BOOST_AUTO_TEST_CASE(an_elastic_run_without_collisions_measures_no_frequency) {
  EnsembleSpec spec;
  spec.particles = 100;
  spec.restitutions = {1.0};
  spec.seeds = 2;
  spec.t_end_elastic = 1e-9;
  std::vector<RunOutcome> runs(2);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    runs[i].ok = true;
    runs[i].result.parameters = expand(spec)[i];
    runs[i].result.collisions = 0;
    runs[i].result.samples.resize(2);
    runs[i].result.samples[1].t = 1e-9;
  }
  const auto points = summarize(spec, runs, WindowRule{});
  BOOST_TEST_REQUIRE(points.size() == 1u);
  BOOST_TEST(points[0].summary.runs == 0);
  BOOST_TEST(points[0].summary.failed == 2);
  BOOST_TEST(std::isnan(points[0].collision_ratio.value));
  BOOST_TEST(points[0].summary.notes.at(0).reason.find("no collision by t_end = 1e-09") !=
             std::string::npos);
}

// The elastic collision frequency leaves out the first half of the run, where a shuffled gas's
// frequency still rises: a run at Enskog's frequency over its second half, below it before, reads
// 1 (from t = 0 it would read 0.95).
BOOST_AUTO_TEST_CASE(elastic_collision_frequency_leaves_out_the_start_up_transient) {
  sim::RunResult run;
  auto& p = run.parameters;
  p.dimension = 2;
  p.particles = 1000000;  // counts of 10^7: rounding them to integers moves the ratio by < 1e-7
  p.density = 0.1;
  p.restitution = 1.0;
  const double omega = theory::enskog_collision_frequency(2, p.density, 1.0);
  for (double t : {0.0, 10.0, 50.0, 80.0, 100.0, 150.0, 200.0}) {
    sim::Sample s;
    s.t = t;
    s.temperature = 1.0;
    // ω/2 collisions per particle and unit time: 0.8 ω up to t = 50, ω from there.
    const double rate = 0.5 * p.particles * omega;
    s.collisions = static_cast<std::uint64_t>(
        std::llround(rate * (t <= 50.0 ? 0.8 * t : 0.8 * 50.0 + (t - 50.0))));
    run.samples.push_back(s);
  }
  run.collisions = run.samples.back().collisions;
  BOOST_TEST(collision_frequency_ratio(run) == 1.0, boost::test_tools::tolerance(1e-6));
  run.samples.resize(1);  // a run sampled only at t = 0 measures no frequency
  BOOST_TEST(std::isnan(collision_frequency_ratio(run)));
}

// Two summary points at density 0.05, mode none, restitutions 0.9 and 1, of `runs` runs each,
// and the lines of their summary CSV that start with `prefix` (by default the data rows) as
// write_summary_csv writes them with the fit-window rule `window`.
struct SummaryPair {
  EnsembleSpec spec;
  WindowRule window{};
  std::vector<PointResult> points{2};
  explicit SummaryPair(int runs) {
    spec.restitutions = {0.9, 1.0};
    spec.seeds = runs;
    for (std::size_t i = 0; i < points.size(); ++i) {
      points[i].summary.density = 0.05;
      points[i].summary.restitution = spec.restitutions[i];
      points[i].summary.mode = "none";
      points[i].summary.runs = runs;
    }
  }
  std::vector<std::string> rows(const std::string& prefix = "0.05,") const {
    const auto path = std::filesystem::temp_directory_path() /
                      ("molchaos_summary_" + std::to_string(::getpid()) + ".csv");
    write_summary_csv(spec, points, window, "test", path.string());
    std::ifstream in(path);
    std::vector<std::string> found;
    for (std::string line; std::getline(in, line);)
      if (line.starts_with(prefix)) found.push_back(line);
    std::filesystem::remove(path);
    return found;
  }
};

// The summary CSV of a point with one run: the values, but no standard errors (nan, not 0).
BOOST_AUTO_TEST_CASE(summary_of_one_run_has_no_error_bars) {
  SummaryPair s(1);
  s.points[0].summary.A = {20.5, 0.0};
  s.points[0].A_theory = {21.3, 2.5e-14};
  s.points[1].collision_ratio = {1.01, 0.0};
  const auto rows = s.rows();
  BOOST_TEST_REQUIRE(rows.size() == 2u);
  BOOST_TEST(rows[0].starts_with("0.05,0.9,edmd,none,20.5,nan,1,0,21.3,2.5e-14,0,nan,0,nan,"));
  BOOST_TEST(rows[1].ends_with(",1.01,nan"));
}

// Columns that do not apply to a point are nan, not 0: A, A_theory, mean_dyad, a2 and the
// breakdown time at eps = 1, collision_ratio at eps < 1, the breakdown time without a breakdown.
BOOST_AUTO_TEST_CASE(summary_columns_that_do_not_apply_are_nan) {
  SummaryPair s(3);
  s.points[0].summary.A = {20.5, 0.1};
  s.points[0].A_theory = {21.3, 2.5e-14};
  s.points[0].summary.mean_dyad = {-0.5, 0.02};
  s.points[0].summary.a2 = {0.01, 0.003};
  s.points[1].collision_ratio = {1.01, 0.02};
  const auto rows = s.rows();
  BOOST_TEST_REQUIRE(rows.size() == 2u);
  BOOST_TEST(rows[0] ==
             "0.05,0.9,edmd,none,20.5,0.1,3,0,21.3,2.5e-14,-0.5,0.02,0.01,0.003,0,nan,"
             "nan,nan,nan");
  BOOST_TEST(rows[1] == "0.05,1,edmd,none,nan,nan,3,0,nan,nan,nan,nan,nan,nan,0,nan,nan,1.01,0.02");
}

// The summary's header states the fit window it was made with, every threshold to the last digit,
// so that its A can be recomputed from the runs' T(t) alone.
BOOST_AUTO_TEST_CASE(summary_header_states_the_fit_window) {
  SummaryPair s(3);
  s.window.start_collisions_per_particle = 2.5;
  s.window.density_mode_threshold = 7.123456789012345;
  s.window.velocity_mode_threshold = 4.25;
  const auto lines = s.rows("# window:");
  BOOST_TEST_REQUIRE(lines.size() == 1u);
  BOOST_TEST(lines[0] + "\n" == window_rule_line(s.window));
  for (const char* part :
       {"at least 2.5 collisions", "density mode > 7.123456789012345", "velocity mode > 4.25"})
    BOOST_TEST(lines[0].find(part) != std::string::npos, part);
}

// The report page embeds an animation as a GIF data URI and a still figure as a PNG one.
BOOST_AUTO_TEST_CASE(report_html_embeds_gif_and_png_by_type) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "molchaos_report_html_types";
  fs::create_directories(dir);
  std::ofstream(dir / "a.gif", std::ios::binary) << "GIF89a";
  std::ofstream(dir / "b.png", std::ios::binary) << "\x89PNG";
  const std::string html =
      report_html("# r\n\n![a.gif](a.gif)\n\n![b.png](b.png)\n", dir.string());
  BOOST_TEST(html.find("data:image/gif;base64," + base64("GIF89a")) != std::string::npos);
  BOOST_TEST(html.find("data:image/png;base64," + base64("\x89PNG")) != std::string::npos);
  fs::remove_all(dir);
}
