// The quadrature against every exact value the symbolic derivation prints (generated at build time
// from theory/derivations/collision_moments.py): all terms a2^i a3^j b^k of μ2, μ4, μ6 for d = 2, 3
// and both dyads, at several restitutions, and the molecular-chaos contact averages. Agreement to
// 1e-10 (relative to μ_p(0,0)) and within the quadrature's own error estimate.
#define BOOST_TEST_MODULE theory_exact_coefficients
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/exact_values.hpp"

using namespace molchaos::theory;

BOOST_AUTO_TEST_CASE(every_moment_term_matches_its_exact_value) {
  std::map<std::tuple<int, int, int, double>, ExpansionTable> tables;
  int checked = 0;
  for (const exact::MomentTerm& t : exact::k_moment_terms) {
    for (double eps : {0.15, 0.6, 0.95}) {
      const auto key = std::make_tuple(t.dimension, t.moment, t.dyad_factor, eps);
      if (!tables.count(key))
        tables[key] = expand_collision_moment(t.dimension, t.moment, eps, t.dyad_factor, {},
                                              SonineTerms::a2_a3);
      const ExpansionTable& table = tables[key];
      const Estimate q = std::string(t.term) == "1" ? table.base : table.term(t.term).integral;
      const double x = exact::integral(t, eps);
      const double scale = std::abs(table.base.value);
      BOOST_TEST_INFO("d = " << t.dimension << ", p = " << t.moment << ", dyad " << t.dyad_factor
                             << ", term " << t.term << ", eps = " << eps << ": " << q.value
                             << " vs " << x << " = " << t.integral_text);
      BOOST_TEST(std::abs(q.value - x) <= 1e-10 * scale);
      BOOST_TEST(std::abs(q.value - x) <= q.error + 1e-15 * scale);
      ++checked;
    }
  }
  BOOST_TEST(checked == 2 * 3 * 12 * 3 + 1 * 3 * 12 * 3);  // d = 2: two dyads, d = 3: one
}

BOOST_AUTO_TEST_CASE(molecular_chaos_contact_averages) {
  // ⟨D⟩ over colliding uncorrelated Maxwellian pairs and the collision integral J_1.
  for (int d : {2, 3}) {
    const ContactIntegrals J = contact_integrals(d, 0.0, k_paper_dyad_factor);
    const auto* j1 = exact::find_contact_term(d, k_paper_dyad_factor, "collision_integral_J1");
    const auto* dyad = exact::find_contact_term(d, k_paper_dyad_factor, "dyad");
    BOOST_REQUIRE(j1 != nullptr);
    BOOST_REQUIRE(dyad != nullptr);
    const double root_2pi = std::sqrt(2.0 * std::numbers::pi);
    BOOST_TEST(std::abs(J.one.value - root_2pi * j1->coefficients[0]) <= 1e-10 * J.one.value);
    BOOST_TEST(std::abs(J.mean_dyad(0.0).value - dyad->coefficients[0]) <= 1e-10);
    BOOST_TEST(dyad->coefficients[0] == -0.5);
  }
}
