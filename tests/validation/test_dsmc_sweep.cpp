// A short sweep with method = dsmc: the DSMC gas obeys molecular chaos by construction, so the
// amplitude A of its Haff law agrees with kinetic theory's within the ensemble's errors, by the
// suite's agreement rule (3 combined standard errors).
#define BOOST_TEST_MODULE validation_dsmc_sweep
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "molchaos/theory/agreement.hpp"
#include "molchaos/theory/sonine_hcs.hpp"
#include "molchaos/validation/ensemble.hpp"
#include "molchaos/validation/pair_correlations.hpp"
#include "molchaos/validation/verdict.hpp"

using namespace molchaos;
using namespace molchaos::validation;

BOOST_AUTO_TEST_CASE(dsmc_sweep_cools_as_kinetic_theory) {
  EnsembleSpec spec;
  spec.methods = {sim::Method::dsmc};
  spec.particles = 5000;
  spec.densities = {0.1};
  spec.restitutions = {0.8};
  spec.seeds = 20;  // DSMC runs take milliseconds; 20 seeds make the error bar itself reliable
  spec.base_seed = 2026;
  spec.t_end_in_tau0 = 3.0;
  const std::vector<sim::Parameters> runs = expand(spec);
  for (const sim::Parameters& p : runs) BOOST_TEST_REQUIRE((p.method == sim::Method::dsmc));

  SweepOptions options;
  options.progress = false;
  options.version = "test";
  const auto points = summarize(spec, run_sweep(runs, options), WindowRule{});
  BOOST_TEST_REQUIRE(points.size() == 1u);
  const PointResult& point = points.front();
  BOOST_TEST_REQUIRE(point.summary.runs == spec.seeds);
  BOOST_TEST_REQUIRE(point.summary.A.error > 0.0);
  const theory::Agreement a = theory::agreement(point.summary.A, point.A_theory);
  BOOST_TEST_MESSAGE("DSMC n = 0.1, eps = 0.8: A = "
                     << point.summary.A.value << " ± " << point.summary.A.error << ", theory "
                     << point.A_theory.value << " ± " << point.A_theory.error);
  BOOST_TEST(a.agrees);
}

// The flux-shuffled MD gas is the suite's molecular-chaos reference among the MD gases: its A
// equals the DSMC gas's at the same state points (a global χ² over two points, each with its
// ensemble errors), while the original gas at n = 0.1, ε = 0.8 does not (its velocity
// correlations slow the cooling by a few per cent, many standard errors here).
BOOST_AUTO_TEST_CASE(flux_shuffled_md_cools_as_dsmc) {
  SweepOptions options;
  options.progress = false;
  options.version = "test";
  auto points_of = [&](sim::Method method, sim::Randomization mode, int seeds) {
    EnsembleSpec spec;
    spec.methods = {method};
    spec.particles = 2000;
    spec.densities = {0.1};
    spec.restitutions = {0.8, 0.9};
    spec.modes = {mode};
    spec.seeds = seeds;
    spec.base_seed = 77;
    return summarize(spec, run_sweep(expand(spec), options), WindowRule{});
  };
  const auto dsmc = points_of(sim::Method::dsmc, sim::Randomization::none, 24);
  const auto flux = points_of(sim::Method::edmd, sim::Randomization::flux, 6);
  const auto original = points_of(sim::Method::edmd, sim::Randomization::none, 16);
  BOOST_TEST_REQUIRE(dsmc.size() == 2u);
  double chi2 = 0.0;
  for (std::size_t k = 0; k < dsmc.size(); ++k) {
    const theory::Agreement a = theory::agreement(flux[k].summary.A, dsmc[k].summary.A);
    BOOST_TEST_REQUIRE(a.difference_in_se.has_value());
    BOOST_TEST_MESSAGE("eps = " << dsmc[k].summary.restitution << ": flux "
                                << flux[k].summary.A.value << " ± " << flux[k].summary.A.error
                                << ", DSMC " << dsmc[k].summary.A.value << " ± "
                                << dsmc[k].summary.A.error);
    const double z = normal_score(*a.difference_in_se, flux[k].summary.runs - 1);
    chi2 += z * z;
  }
  BOOST_TEST(chi_square_p_value(chi2, 2) >= k_global_p_threshold);
  const theory::Agreement slower = theory::agreement(original[0].summary.A, dsmc[0].summary.A);
  BOOST_TEST_MESSAGE("eps = 0.8: original " << original[0].summary.A.value << " ± "
                                            << original[0].summary.A.error);
  BOOST_TEST(!slower.agrees);
  BOOST_TEST(original[0].summary.A.value > dsmc[0].summary.A.value);
}

// DSMC solves the kinetic equation without the Sonine truncation: its a2 in the homogeneous
// cooling state agrees with the improved theory (a2² and a3 kept) and, at strong dissipation,
// not with the first-Sonine a2 (van Noije & Ernst) that the paper quotes. One χ² per level over
// three restitutions.
BOOST_AUTO_TEST_CASE(dsmc_a2_follows_the_improved_sonine_theory) {
  EnsembleSpec spec;
  spec.methods = {sim::Method::dsmc};
  spec.particles = 5000;
  spec.densities = {0.1};
  spec.restitutions = {0.6, 0.7, 0.8};
  spec.seeds = 32;
  spec.base_seed = 4242;
  SweepOptions options;
  options.progress = false;
  options.version = "test";
  const auto points = summarize(spec, run_sweep(expand(spec), options), WindowRule{});
  double chi2_first = 0.0, chi2_improved = 0.0;
  for (const PointResult& p : points) {
    const theory::HcsSonine levels = theory::hcs_sonine_coefficients(2, p.summary.restitution);
    const auto z = [&](const theory::Estimate& a2) {
      const theory::Agreement a = theory::agreement(p.summary.a2, a2);
      return normal_score(a.difference_in_se.value_or(0.0), p.summary.runs - 1);
    };
    BOOST_TEST_MESSAGE("eps = " << p.summary.restitution << ": a2 DSMC " << p.summary.a2.value
                                << " ± " << p.summary.a2.error << ", first Sonine "
                                << levels.first_sonine.a2.value << ", with a2^2 and a3 "
                                << levels.a2_a3.a2.value);
    chi2_first += std::pow(z(levels.first_sonine.a2), 2);
    chi2_improved += std::pow(z(levels.a2_a3.a2), 2);
  }
  BOOST_TEST(chi_square_p_value(chi2_improved, 3) >= k_global_p_threshold);
  BOOST_TEST(chi_square_p_value(chi2_first, 3) < k_global_p_threshold);
}
