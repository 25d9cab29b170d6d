// The break-down study's compact set in d = 3 (BreakdownSpec::three_dimensional): its boxes lie on
// the sides of L_c the theory gives, and the linear regime (growth of the largest shear mode above
// L_c, the level of the largest mode below) agrees with the simulation, no free parameter.
#define BOOST_TEST_MODULE validation_breakdown_3d
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "linear_rows.hpp"
#include "molchaos/theory/hydrodynamics.hpp"
#include "molchaos/validation/breakdown.hpp"

using namespace molchaos;
using namespace molchaos::validation;

namespace {

double box_side(std::int64_t particles, double density) {
  return std::cbrt(static_cast<double>(particles) / density);
}

}  // namespace

// The state point is chosen from the theory: the large box above L_c = 2π/k⊥ and below the heat
// mode's 2π/k∥ (only shear modes grow), the small box below L_c, both ≲ 20 000 spheres, the
// packing fraction ≤ 0.2.
BOOST_AUTO_TEST_CASE(boxes_straddle_the_critical_size) {
  const auto spec = BreakdownSpec::three_dimensional();
  BOOST_TEST(spec.dimension == 3);
  const auto c = theory::transport_coefficients({3, spec.density, spec.restitution, std::nullopt});
  BOOST_TEST(c.packing_fraction <= 0.2);
  const double critical = theory::critical_box_size(c);
  const double heat = 2 * M_PI / theory::critical_heat_wavenumber(c);
  const double large = box_side(spec.unstable_particles, spec.density);
  const double small = box_side(spec.stable_particles, spec.density);
  BOOST_TEST_MESSAGE("L_c = " << critical << ", heat " << heat << ", boxes " << large << ", "
                              << small);
  BOOST_TEST(large > critical);
  BOOST_TEST(large < heat);
  BOOST_TEST(small < critical);
  BOOST_TEST(spec.unstable_particles <= 20000);
  BOOST_TEST(theory::shear_mode_rate(c, 2 * M_PI / large) > 0);
  BOOST_TEST(theory::shear_mode_rate(c, 2 * M_PI / small) < 0);
  // the fit window [2, fit_max] of the largest mode is reached within the runs
  const double tau = theory::collisions_to_reach(c, 2 * M_PI / large, spec.fit_max_transverse);
  BOOST_TEST(tau < spec.collisions_per_particle);
}

// Growth rate and stationary level within 3 jackknife standard errors of linear hydrodynamics.
// The reproduction's full set (2 × 32 runs, a few CPU seconds in d = 3).
BOOST_AUTO_TEST_CASE(linear_hydrodynamics_in_three_dimensions) {
  const auto rows = breakdown_study(BreakdownSpec::three_dimensional());
  BOOST_TEST_MESSAGE(breakdown_markdown(rows));
  for (const auto& r : rows) BOOST_TEST(r.dimension == 3);
  BOOST_TEST(check_linear_rows(rows) ==
             3);  // |m|² = 1 and 2 grow at 24.1σ (2 rows), one stable level
}
