// validation/: the Haff fit on exact data, the window rule, straight-line fits, ensemble
// statistics, seeds, and the cache (round trip, corrupt entries recomputed).
#define BOOST_TEST_MODULE validation_unit
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
}

BOOST_AUTO_TEST_CASE(mean_and_standard_error_values) {
  const Measurement m = mean_and_standard_error({1.0, 2.0, 3.0, 4.0});
  BOOST_TEST(m.value == 2.5);
  BOOST_TEST(std::abs(m.error - std::sqrt(5.0 / 3.0 / 4.0)) <= 1e-15);
  BOOST_TEST(mean_and_standard_error({7.0}).error == 0.0);
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

// A point where no run succeeded has no A: nan (printed as such in every table), not 0.
BOOST_AUTO_TEST_CASE(a_point_without_successful_runs_has_no_value) {
  const PointSummary s = summarize_point({}, WindowRule{});
  BOOST_TEST(s.runs == 0);
  BOOST_TEST(std::isnan(s.A.value));
  BOOST_TEST(std::isnan(s.A.error));
  BOOST_TEST(std::isnan(s.a2.value));
  BOOST_TEST(std::isnan(s.mean_dyad.value));
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
