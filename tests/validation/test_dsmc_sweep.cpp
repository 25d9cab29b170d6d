// A short sweep with method = dsmc: the DSMC gas obeys molecular chaos by construction, so the
// amplitude A of its Haff law agrees with kinetic theory's within the ensemble's errors, by the
// suite's agreement rule (3 combined standard errors).
#define BOOST_TEST_MODULE validation_dsmc_sweep
#include <boost/test/unit_test.hpp>

#include "molchaos/theory/agreement.hpp"
#include "molchaos/validation/ensemble.hpp"

using namespace molchaos;
using namespace molchaos::validation;

BOOST_AUTO_TEST_CASE(dsmc_sweep_cools_as_kinetic_theory) {
  EnsembleSpec spec;
  spec.method = sim::Method::dsmc;
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
