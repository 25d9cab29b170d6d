// CI accuracy assertions on a reduced ensemble (N = 5000, 6 seeds), tolerances from the
// ensemble's own standard errors:
//  - elastic limit: ω/ω_Enskog = 1 for the modes that claim molecular chaos (none, flux), and
//    the paper's shuffle measurably above 1;
//  - the flux-shuffled gas cools with the kinetic-theory τ0 at two (ε, n) points;
//  - the original gas at ε = 0.8 cools measurably more slowly than that.
#define BOOST_TEST_MODULE validation_accuracy
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <map>

#include "molchaos/validation/ensemble.hpp"

using namespace molchaos;
using namespace molchaos::validation;

namespace {
SweepOptions no_cache() {
  SweepOptions o;
  o.progress = false;
  o.version = "test";
  return o;
}
EnsembleSpec reduced(double density, std::vector<double> restitutions,
                     std::vector<sim::Randomization> modes) {
  EnsembleSpec s;
  s.particles = 5000;
  s.densities = {density};
  s.restitutions = std::move(restitutions);
  s.modes = std::move(modes);
  s.seeds = 6;
  s.base_seed = 2026;
  s.t_end_elastic = 100.0;
  s.t_end_in_tau0 = 3.0;
  return s;
}
}  // namespace

BOOST_AUTO_TEST_CASE(elastic_limit_collision_frequency) {
  using sim::Randomization;
  const auto spec =
      reduced(0.1, {1.0}, {Randomization::none, Randomization::flux, Randomization::paper});
  const auto points = summarize(spec, run_sweep(expand(spec), no_cache()), WindowRule{});
  for (const auto& p : points) {
    const auto& r = p.collision_ratio;
    BOOST_TEST_MESSAGE("n = 0.1, " << p.summary.mode << ": omega/omega_Enskog = " << r.value
                                   << " ± " << r.error);
    BOOST_TEST_REQUIRE(r.error > 0.0);
    if (p.summary.mode == "paper")
      BOOST_TEST(r.value - 1.0 > 3.0 * r.error);  // the paper's shuffle raises the collision rate
    else
      BOOST_TEST(std::abs(r.value - 1.0) <= 3.0 * r.error);
  }
}

BOOST_AUTO_TEST_CASE(randomized_gas_cools_as_kinetic_theory_and_original_more_slowly) {
  using sim::Randomization;
  struct Case {
    double density, restitution;
  };
  for (const Case c : {Case{0.05, 0.9}, Case{0.1, 0.8}}) {
    const auto spec =
        reduced(c.density, {c.restitution}, {Randomization::flux, Randomization::none});
    const auto points = summarize(spec, run_sweep(expand(spec), no_cache()), WindowRule{});
    const auto& flux = points.at(0);
    const auto& original = points.at(1);
    BOOST_TEST_REQUIRE(flux.summary.runs >= 5);
    const double se = std::hypot(flux.summary.A.error, flux.A_theory.error);
    BOOST_TEST_MESSAGE("n = " << c.density << ", eps = " << c.restitution
                              << ": A_flux = " << flux.summary.A.value << " ± "
                              << flux.summary.A.error << ", theory " << flux.A_theory.value
                              << ", A_original = " << original.summary.A.value << " ± "
                              << original.summary.A.error);
    BOOST_TEST(std::abs(flux.summary.A.value - flux.A_theory.value) <= 3.0 * se);
    if (c.restitution == 0.8) {
      // Paired by seed (common initial states): A_original − A_flux > 3 standard errors.
      std::map<std::uint64_t, double> a_flux(flux.summary.A_by_seed.begin(),
                                             flux.summary.A_by_seed.end());
      std::vector<double> diff;
      for (const auto& [seed, A] : original.summary.A_by_seed)
        if (a_flux.count(seed)) diff.push_back(A - a_flux[seed]);
      const Measurement d = mean_and_standard_error(diff);
      BOOST_TEST_MESSAGE("A_original - A_flux = " << d.value << " ± " << d.error);
      BOOST_TEST_REQUIRE(diff.size() >= 4u);
      BOOST_TEST(d.value > 3.0 * d.error);
    }
  }
}
