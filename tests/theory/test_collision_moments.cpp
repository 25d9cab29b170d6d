// μ_p by quadrature against exact results derived independently (by hand and symbolically in
// theory/derivations/collision_moments.py): μ2(0,0), the expansion coefficients, μ4 in d = 2,
// the elastic limit, exactness of the Gauss–Hermite part, and the quadrature's error estimate.
#define BOOST_TEST_MODULE theory_collision_moments
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/gauss_rules.hpp"

using namespace molchaos::theory;

namespace {
constexpr double k_rel = 1e-9;  // the agreement asked of every coefficient and closed form
QuadratureOptions tight() {
  QuadratureOptions q;
  q.relative_tolerance = 1e-11;
  return q;
}
bool close(double computed, double exact, double rel = k_rel) {
  return std::abs(computed - exact) <= rel * std::abs(exact);
}
}  // namespace

BOOST_AUTO_TEST_CASE(maxwellian_mu2_closed_form) {
  // μ2(0,0) = (1 − ε²) √(2π)/2 (d = 2), (1 − ε²) √(2π) (d = 3).
  const double root_2pi = std::sqrt(2.0 * std::numbers::pi);
  for (double e : {0.1, 0.5, 0.93}) {
    const Estimate m2 = mu2(2, e, 0.0, 0.0, tight());
    const Estimate m3 = mu2(3, e, 0.0, 0.0, tight());
    BOOST_TEST(close(m2.value, (1 - e * e) * root_2pi / 2));
    BOOST_TEST(close(m3.value, (1 - e * e) * root_2pi));
    BOOST_TEST(m2.error <= 1e-10 * m2.value);
  }
  BOOST_TEST(std::abs(mu2_maxwell_prefactor(2) - root_2pi / 2) <= 1e-15);
}

BOOST_AUTO_TEST_CASE(elastic_limit_dissipates_nothing) {
  for (int d : {2, 3}) {
    const Estimate m = mu2(d, 1.0, 0.1, 0.2, tight());
    BOOST_TEST(std::abs(m.value) <= 1e-14);
  }
}

BOOST_AUTO_TEST_CASE(mu2_coefficients_printed_dyad) {
  // Exact values (theory/derivations/collision_moments.py; 3/16, 9/1024, b by hand in
  // doc/theory.md). The paper prints −63/40 for b; the integral gives −3/2.
  struct Row {
    const char* term;
    double exact;
  };
  const Row rows2[] = {{"a2", 3.0 / 16},
                       {"a2^2", 9.0 / 1024},
                       {"b", -1.5},
                       {"a2*b", -21.0 / 32},
                       {"a2^2*b", 93.0 / 2048}};
  const Row rows3[] = {{"a2", 3.0 / 16}, {"a2^2", 9.0 / 1024}, {"b", -1.5}};
  const ExpansionTable t2 = expand_collision_moment(2, 2, 0.7, k_paper_dyad_factor, tight());
  for (const Row& r : rows2) {
    BOOST_TEST_INFO("d = 2, term " << r.term);
    BOOST_TEST(close(t2.term(r.term).coefficient.value, r.exact));
    BOOST_TEST(std::abs(t2.term(r.term).coefficient.value - r.exact) <=
               3.0 * t2.term(r.term).coefficient.error + 1e-15);
  }
  const ExpansionTable t3 = expand_collision_moment(3, 2, 0.7, k_paper_dyad_factor, tight());
  for (const Row& r : rows3) {
    BOOST_TEST_INFO("d = 3, term " << r.term);
    BOOST_TEST(close(t3.term(r.term).coefficient.value, r.exact));
  }
  BOOST_TEST(std::abs(t2.term("b").coefficient.value - (-63.0 / 40.0)) > 0.07);
}

BOOST_AUTO_TEST_CASE(mu2_coefficients_traceless_dyad_in_two_dimensions) {
  const ExpansionTable t = expand_collision_moment(2, 2, 0.7, 2.0, tight());
  BOOST_TEST(close(t.term("b").coefficient.value, -0.75));
  BOOST_TEST(close(t.term("a2*b").coefficient.value, -21.0 / 64));
  BOOST_TEST(close(t.term("a2^2*b").coefficient.value, 93.0 / 4096));
}

BOOST_AUTO_TEST_CASE(mu2_coefficients_do_not_depend_on_restitution) {
  const ExpansionTable a = expand_collision_moment(2, 2, 0.2, k_paper_dyad_factor, tight());
  const ExpansionTable b = expand_collision_moment(2, 2, 0.95, k_paper_dyad_factor, tight());
  for (const auto& t : a.terms)
    BOOST_TEST(close(t.coefficient.value, b.term(t.name).coefficient.value));
}

BOOST_AUTO_TEST_CASE(mu4_in_two_dimensions) {
  // Symbolic result: μ4(0,0) = √(2π)(1 − ε²)(2ε² + 7)/4; a2 coefficient
  // (30ε³ − 30ε² + 177ε − 209)/(16(ε − 1)(2ε² + 7)); b coefficient (dyad 3)
  // −(10ε² + 19)/(2(2ε² + 7)).
  const double e = 0.8;
  const ExpansionTable t = expand_collision_moment(2, 4, e, k_paper_dyad_factor, tight());
  const double root_2pi = std::sqrt(2.0 * std::numbers::pi);
  BOOST_TEST(close(t.base.value, root_2pi * (1 - e * e) * (2 * e * e + 7) / 4));
  BOOST_TEST(close(t.term("a2").coefficient.value, (30 * e * e * e - 30 * e * e + 177 * e - 209) /
                                                       (16 * (e - 1) * (2 * e * e + 7))));
  BOOST_TEST(close(t.term("b").coefficient.value, -(10 * e * e + 19) / (2 * (2 * e * e + 7))));
}

BOOST_AUTO_TEST_CASE(full_integrand_equals_its_expansion) {
  // μ2(a2, b) of the non-linearised integrand is the polynomial of the coefficients.
  const double e = 0.85, a2 = -0.05, b = 0.03;
  const ExpansionTable t = expand_collision_moment(2, 2, e, k_paper_dyad_factor, tight());
  const Estimate full = mu2(2, e, a2, b, tight());
  BOOST_TEST(close(full.value, t.base.value * t.ratio(a2, b)));
}

BOOST_AUTO_TEST_CASE(hermite_part_is_exact) {
  // Raising the Gauss–Hermite order beyond the exact one changes nothing but rounding.
  for (int d : {2, 3}) {
    QuadratureOptions exact = tight(), higher = tight();
    higher.hermite_order = exact_hermite_order(2) + 2;
    const double a = collision_moment(d, 2, 0.6, 0.2, 0.1, 3.0, exact).value;
    const double b = collision_moment(d, 2, 0.6, 0.2, 0.1, 3.0, higher).value;
    BOOST_TEST(std::abs(a - b) <= 1e-13 * std::abs(a));
  }
  // One order too low is detectably wrong for the highest term (so the test can fail).
  QuadratureOptions low = tight();
  low.hermite_order = 3;
  const double wrong = collision_moment(2, 2, 0.6, 0.5, 0.5, 3.0, low).value;
  const double right = collision_moment(2, 2, 0.6, 0.5, 0.5, 3.0, tight()).value;
  BOOST_TEST(std::abs(wrong - right) > 1e-6 * std::abs(right));
}

BOOST_AUTO_TEST_CASE(error_estimate_is_honest) {
  // At a loose tolerance the estimate must still bound the true error (known closed form).
  const double root_2pi = std::sqrt(2.0 * std::numbers::pi);
  for (double tol : {1e-4, 1e-6, 1e-8}) {
    QuadratureOptions q;
    q.relative_tolerance = tol;
    const Estimate m = mu2(2, 0.5, 0.0, 0.0, q);
    const double exact = 0.75 * root_2pi / 2;
    BOOST_TEST_INFO("tolerance " << tol);
    BOOST_TEST(std::abs(m.value - exact) <= m.error + 1e-15);
    BOOST_TEST(m.error <= 10 * tol * exact);
  }
}

BOOST_AUTO_TEST_CASE(bad_arguments) {
  BOOST_CHECK_THROW(collision_moment(2, 3, 0.5, 0, 0, 3), std::invalid_argument);
  BOOST_CHECK_THROW(collision_moment(4, 2, 0.5, 0, 0, 3), std::invalid_argument);
  BOOST_CHECK_THROW(collision_moment(2, 2, 0.0, 0, 0, 3), std::invalid_argument);
  BOOST_CHECK_THROW(collision_moment(2, 2, 1.5, 0, 0, 3), std::invalid_argument);
  BOOST_CHECK_THROW(expand_collision_moment(2, 2, 1.0, 3), std::invalid_argument);
  QuadratureOptions q;
  q.method = QuadratureMethod::adaptive;
  q.relative_tolerance = 0.0;
  BOOST_CHECK_THROW(mu2(2, 0.5, 0, 0, q), std::invalid_argument);
  q.relative_tolerance = 0.5 * k_min_relative_tolerance;
  BOOST_CHECK_THROW(mu2(2, 0.5, 0, 0, q), std::invalid_argument);
  BOOST_CHECK_THROW(collision_moment(2, 8, 0.5, 0, 0, 3), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(gauss_error_estimate_detects_too_low_orders) {
  // Laguerre rules below the exact order are wrong for the highest-degree terms, and the estimate
  // (difference to the next order) must cover the true error (closed form 93/2048).
  QuadratureOptions low;
  low.laguerre_order = 2;
  const ExpansionTable t = expand_collision_moment(2, 2, 0.7, k_paper_dyad_factor, low);
  const Estimate& c = t.term("a2^2*b").coefficient;
  BOOST_TEST(std::abs(c.value - 93.0 / 2048) > 1e-8);
  BOOST_TEST(std::abs(c.value - 93.0 / 2048) <= c.error);
  // At the exact order the estimate is at rounding level.
  const ExpansionTable exact = expand_collision_moment(2, 2, 0.7, k_paper_dyad_factor);
  BOOST_TEST(exact.term("a2^2*b").coefficient.error <= 1e-13);
  BOOST_TEST(exact.term("a2^2*b").coefficient.error >= 0.0);
}

BOOST_AUTO_TEST_CASE(contact_integrals_closed_forms) {
  // J_1 = ∫Θ|g·e|φφ = √(2π) (d = 2), 2√(2π) (d = 3); ⟨D⟩_coll = −1/2 for uncorrelated
  // Maxwellian pairs with the printed dyad in both dimensions (doc/theory.md).
  const double root_2pi = std::sqrt(2.0 * std::numbers::pi);
  for (int d : {2, 3}) {
    const ContactIntegrals J = contact_integrals(d, 0.0, k_paper_dyad_factor, tight());
    BOOST_TEST(close(J.one.value, d == 2 ? root_2pi : 2 * root_2pi));
    BOOST_TEST(close(J.mean_dyad(0.0).value, -0.5));
    // Round trip: the b that produces a mean dyad is recovered from it.
    const ContactIntegrals Ja = contact_integrals(d, -0.02, k_paper_dyad_factor, tight());
    for (double b : {-0.05, 0.0, 0.08}) {
      const Estimate m = Ja.mean_dyad(b);
      BOOST_TEST(std::abs(Ja.b_from_mean_dyad(m.value, 0.0).value - b) <= 1e-9);
    }
  }
}
