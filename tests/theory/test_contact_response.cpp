// Contact averages over colliding pairs under the paper's ansatz, to first order in a2 and b, by
// quadrature against the symbolic derivation (exact rationals, generated header) for d = 2, 3 and
// both dyads; and the series against the full (non-expanded) quadrature at small a2, b.
#define BOOST_TEST_MODULE theory_contact_response
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <utility>

#include "molchaos/theory/contact_response.hpp"
#include "molchaos/theory/exact_values.hpp"

using namespace molchaos::theory;

BOOST_AUTO_TEST_CASE(coefficients_match_the_symbolic_derivation) {
  int checked = 0;
  for (int d : {2, 3}) {
    for (double dyad : {3.0, static_cast<double>(d)}) {
      if (d == 3 && dyad == 3.0 && checked == 2 * 5 * 4 + 5 * 4) continue;  // printed = traceless
      const ContactResponse r = contact_response(d, dyad);
      const std::pair<const char*, const ResponseSeries*> rows[] = {
          {"normal_product", &r.normal_product},
          {"velocity_product", &r.velocity_product},
          {"dyad", &r.dyad},
          {"collision_frequency_ratio", &r.collision_frequency_ratio},
          {"dissipation_ratio", &r.dissipation_ratio}};
      for (const auto& [name, series] : rows) {
        const exact::ContactTerm* x = exact::find_contact_term(d, dyad, name);
        BOOST_REQUIRE(x != nullptr);
        const Estimate* q[4] = {&series->value, &series->d_a2, &series->d_b, &series->d_a2b};
        for (int k = 0; k < 4; ++k) {
          BOOST_TEST_INFO("d = " << d << ", dyad " << dyad << ", " << name << " coefficient " << k
                                 << ": " << q[k]->value << " vs " << x->texts[k]);
          BOOST_TEST(std::abs(q[k]->value - x->coefficients[k]) <= 1e-10);
          BOOST_TEST(std::abs(q[k]->value - x->coefficients[k]) <= q[k]->error + 1e-15);
          BOOST_TEST(q[k]->error >= 0.0);
          ++checked;
        }
      }
    }
  }
  BOOST_TEST(checked == 3 * 5 * 4);
}

BOOST_AUTO_TEST_CASE(molecular_chaos_values) {
  // ⟨(c1·e)(c2·e)⟩ = ⟨c1·c2⟩ = −1/4 and ⟨D⟩ = −1/2 (printed dyad) for uncorrelated Maxwellian
  // colliding pairs, both dimensions (doc/theory.md §7 by hand).
  for (int d : {2, 3}) {
    const ContactResponse r = contact_response(d, k_paper_dyad_factor);
    BOOST_TEST(std::abs(r.normal_product.value.value + 0.25) <= 1e-13);
    BOOST_TEST(std::abs(r.velocity_product.value.value + 0.25) <= 1e-13);
    BOOST_TEST(std::abs(r.dyad.value.value + 0.5) <= 1e-13);
  }
}

BOOST_AUTO_TEST_CASE(series_against_the_full_average) {
  // The full ⟨D⟩(a2, b) = (J_D + b J_DD)/(J_1 + b J_D) differs from the first-order series by
  // O(a2², b²): at a2 = b = 1e-3 by less than 10·(a2² + b²) (coefficients are O(1)), while the
  // first-order terms are 1e-3 — the test fails if a coefficient is wrong by more than 1 %.
  for (int d : {2, 3}) {
    const double a2 = 1e-3, b = 1e-3;
    const ContactResponse r = contact_response(d, k_paper_dyad_factor);
    const ContactIntegrals J = contact_integrals(d, a2, k_paper_dyad_factor);
    const double full = J.mean_dyad(b).value;
    BOOST_TEST(std::abs(full - r.dyad.at(a2, b)) <= 10.0 * (a2 * a2 + b * b));
    BOOST_TEST(std::abs(full - r.dyad.value.value) > 1e-3);
  }
}
