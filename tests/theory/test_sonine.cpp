// S2 and a2(ε): orthogonality, special values, and a2 from the quadrature of μ2 and μ4 against
// van Noije & Ernst's closed form.
#define BOOST_TEST_MODULE theory_sonine
#include <gsl/gsl_integration.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/sonine.hpp"

using namespace molchaos::theory;

namespace {
// ∫_0^∞ dc c^{d−1} c^{2k} e^{−c²} S2(c²) (radial part of the isotropic average).
double radial_moment(int d, int k) {
  struct P {
    int d, k;
  } p{d, k};
  gsl_function f;
  f.params = &p;
  f.function = [](double c, void* q) {
    auto* s = static_cast<P*>(q);
    return std::pow(c, s->d - 1 + 2 * s->k) * std::exp(-c * c) * sonine_s2(s->d, c * c);
  };
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(200);
  double value = 0, error = 0;
  gsl_integration_qagiu(&f, 0.0, 1e-14, 1e-12, 200, w, &value, &error);
  gsl_integration_workspace_free(w);
  return value;
}
}  // namespace

BOOST_AUTO_TEST_CASE(paper_polynomial_in_two_dimensions) {
  for (double x : {0.0, 0.5, 1.0, 2.0, 7.5})
    BOOST_TEST(std::abs(sonine_s2(2, x) - (0.5 * x * x - 2.0 * x + 1.0)) <= 1e-15);
}

BOOST_AUTO_TEST_CASE(s2_preserves_normalisation_and_temperature) {
  // ⟨S2⟩ = ⟨c² S2⟩ = 0 over the Maxwellian, so f = φ(1 + a2 S2) keeps n and T.
  for (int d : {2, 3}) {
    BOOST_TEST(std::abs(radial_moment(d, 0)) <= 1e-12);
    BOOST_TEST(std::abs(radial_moment(d, 1)) <= 1e-12);
    BOOST_TEST(std::abs(radial_moment(d, 2)) > 0.1);  // ⟨c⁴ S2⟩ ≠ 0 defines a2
  }
}

BOOST_AUTO_TEST_CASE(a2_special_values) {
  for (int d : {2, 3}) {
    BOOST_TEST(a2_first_sonine(d, 1.0) == 0.0);
    BOOST_TEST(std::abs(a2_first_sonine(d, 1.0 / std::numbers::sqrt2)) <= 1e-16);
  }
  // ε → 0: 16 / (9 + 24 d).
  BOOST_TEST(std::abs(a2_first_sonine(2, 1e-12) - 16.0 / 57.0) <= 1e-10);
  BOOST_TEST(std::abs(a2_first_sonine(3, 1e-12) - 16.0 / 81.0) <= 1e-10);
  // Paper's Eq. (25) at ε = 0.9 written out.
  const double e = 0.9;
  BOOST_TEST(std::abs(a2_first_sonine(2, e) - 16 * (1 - e) * (1 - 2 * e * e) /
                                                  (57 - 25 * e + 30 * e * e * (1 - e))) <= 1e-16);
}

BOOST_AUTO_TEST_CASE(a2_from_quadrature_matches_closed_form) {
  // The moment equation μ4 = (d+2)(1+a2)μ2 with quadrature μ2, μ4 must give van Noije–Ernst.
  QuadratureOptions q;
  q.relative_tolerance = 1e-10;
  for (int d : {2, 3}) {
    for (double e : {0.3, 0.93}) {
      const Estimate a2 = a2_from_moments(d, e, q);
      const double exact = a2_first_sonine(d, e);
      BOOST_TEST_INFO("d = " << d << ", eps = " << e << ": " << a2.value << " ± " << a2.error);
      BOOST_TEST(std::abs(a2.value - exact) <= 1e-9 * std::abs(exact) + 1e-13);
      BOOST_TEST(std::abs(a2.value - exact) <= 3.0 * a2.error + 1e-14);
    }
  }
}

BOOST_AUTO_TEST_CASE(a2_rejects_bad_restitution) {
  BOOST_CHECK_THROW(a2_first_sonine(2, 0.0), std::invalid_argument);
  BOOST_CHECK_THROW(a2_first_sonine(2, 1.0000001), std::invalid_argument);
  BOOST_CHECK_THROW(a2_first_sonine(1, 0.5), std::invalid_argument);
}
