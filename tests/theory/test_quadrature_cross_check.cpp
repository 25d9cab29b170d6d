// The two quadratures of the collision integrals against each other. They share only the exact
// centre-of-mass sum: fixed Gauss–Laguerre rules over the relative velocity (the default) against
// nested adaptive GSL QAGIU at tolerance 1e-12 (the independent check).
#define BOOST_TEST_MODULE theory_quadrature_cross_check
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "molchaos/theory/collision_moments.hpp"

using namespace molchaos::theory;

namespace {

// Every term of the table: |gauss − adaptive| ≤ 1e-12 relative to μ_p(0,0) (the agreement the
// suite claims), and within the sum of the two error estimates.
void check_table(int d, int p, double dyad) {
  QuadratureOptions adaptive;
  adaptive.method = QuadratureMethod::adaptive;
  adaptive.relative_tolerance = 1e-12;
  const ExpansionTable g = expand_collision_moment(d, p, 0.6, dyad);
  const ExpansionTable a = expand_collision_moment(d, p, 0.6, dyad, adaptive);
  const double scale = std::abs(g.base.value);
  BOOST_TEST(std::abs(g.base.value - a.base.value) <= 1e-12 * scale);
  for (const auto& t : g.terms) {
    const Estimate& x = t.integral;
    const Estimate& y = a.term(t.name).integral;
    BOOST_TEST_INFO("d = " << d << ", p = " << p << ", dyad " << dyad << ", term " << t.name << ": "
                           << x.value << " vs " << y.value);
    BOOST_TEST(std::abs(x.value - y.value) <= 1e-12 * scale);
    BOOST_TEST(std::abs(x.value - y.value) <= x.error + y.error + 1e-16 * scale);
    BOOST_TEST(x.error >= 0.0);
    BOOST_TEST(y.error >= 0.0);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(mu2_table_two_dimensions) { check_table(2, 2, k_paper_dyad_factor); }

BOOST_AUTO_TEST_CASE(mu2_table_three_dimensions) { check_table(3, 2, k_paper_dyad_factor); }

BOOST_AUTO_TEST_CASE(mu4_tables_and_traceless_dyad) {
  check_table(2, 2, 2.0);
  check_table(2, 4, k_paper_dyad_factor);
  check_table(3, 4, k_paper_dyad_factor);
}
