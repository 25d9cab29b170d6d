// A physics regression of the original gas against its molecular-chaos reference: colliding pairs
// of the inelastic gas (ε = 0.8, n = 0.1, d = 2) arrive with positively correlated normal
// velocities: ⟨(c1·e)(c2·e)⟩ lies above that of the flux-shuffled gas started from the same
// initial states beyond 3 standard errors of the paired difference (the effect the paper's b
// describes). The flux gas's own value is printed beside the first-order molecular-chaos value
// −1/4 + a2/16 for information. On the same runs, the cooling rate taken apart: the directly
// fitted A_orig/A_chaos equals the product of the collision-frequency and energy-loss ratios.
#define BOOST_TEST_MODULE validation_contact_regression
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "molchaos/sim/run.hpp"
#include "molchaos/validation/analysis.hpp"
#include "molchaos/validation/contact_ansatz.hpp"
#include "molchaos/validation/contact_measurement.hpp"
#include "molchaos/validation/correlation_analysis.hpp"
#include "molchaos/validation/ensemble.hpp"
#include "molchaos/validation/verdict.hpp"

using namespace molchaos;
using namespace molchaos::validation;

namespace {

// The original and the flux-shuffled gas from the same relaxed states (ε = 0.8, n = 0.1, d = 2).
const GasPair& runs() {
  static const GasPair pair = [] {
    EnsembleSpec spec;  // the defaults of the Fig. 4 runs (duration, sampling), at a smaller scale
    spec.dimension = 2;
    spec.particles = 4000;
    spec.densities = {0.1};
    spec.restitutions = {0.8};
    spec.modes = {sim::Randomization::none, sim::Randomization::flux};
    spec.seeds = 6;
    spec.contact_statistics = true;
    GasPair gp{2, 0.1, 0.8, {}, {}};
    for (const sim::Parameters& p : expand(spec)) {
      const RunContacts c = measure_contacts(sim::run(p), WindowRule{});
      BOOST_REQUIRE_MESSAGE(c.ok, "run with seed " << p.seed << " has no homogeneous window");
      (p.randomize == sim::Randomization::none ? gp.original : gp.chaos).push_back(c);
    }
    return gp;
  }();
  return pair;
}

}  // namespace

BOOST_AUTO_TEST_CASE(original_gas_has_positive_velocity_correlations_at_contact) {
  const GasPair& gp = runs();
  BOOST_REQUIRE(gp.original.size() == gp.chaos.size());
  std::vector<double> P_flux, a2_flux, paired;
  for (std::size_t s = 0; s < gp.original.size(); ++s) {
    BOOST_REQUIRE(gp.original[s].seed == gp.chaos[s].seed);
    paired.push_back(gp.original[s].measured.P - gp.chaos[s].measured.P);
    P_flux.push_back(gp.chaos[s].measured.P);
    a2_flux.push_back(gp.chaos[s].a2);
  }
  const Measurement shift = mean_and_standard_error(paired);
  BOOST_TEST_MESSAGE("P_original - P_flux = " << shift.value << " +- " << shift.error);
  BOOST_TEST(shift.value > k_agreement_standard_errors * shift.error);

  const Measurement flux = mean_and_standard_error(P_flux);
  const Measurement a2 = mean_and_standard_error(a2_flux);
  const Measurement chaos{molecular_chaos_contact(a2.value).P, a2.error / 16.0};
  BOOST_TEST_MESSAGE("P_flux = " << flux.value << " +- " << flux.error << ", chaos " << chaos.value);
}

BOOST_AUTO_TEST_CASE(cooling_rate_is_collision_frequency_times_energy_loss) {
  // ζ ∝ ω·⟨(g·e)²⟩: A ∝ 1/ζ, so A_orig/A_chaos = (W Y)_chaos/(W Y)_orig run by run, with W the
  // collision frequency over Enskog's and Y the energy loss per collision over its chaos value.
  const CoolingDecompositionRow row = decompose_cooling(runs());
  BOOST_TEST_MESSAGE("A_orig/A_chaos = " << row.A_ratio.value << " +- " << row.A_ratio.error
                                         << ", (W Y)_chaos/(W Y)_orig = " << row.product_ratio.value
                                         << " +- " << row.product_ratio.error << ", difference "
                                         << row.difference.value << " +- " << row.difference.error);
  BOOST_TEST_MESSAGE("ln(W_chaos/W_orig) = " << row.log_frequency.value << " +- "
                                             << row.log_frequency.error << ", ln(Y_chaos/Y_orig) = "
                                             << row.log_dissipation.value << " +- "
                                             << row.log_dissipation.error);
  BOOST_TEST(row.pairs == 6);
  // The effect is resolved (the test has power) and the product accounts for it.
  BOOST_TEST(row.A_ratio.value - 1.0 > k_agreement_standard_errors * row.A_ratio.error);
  BOOST_TEST(std::abs(row.difference.value) < k_agreement_standard_errors * row.difference.error);
}
