// a2, a3 of the homogeneous cooling state beyond the first Sonine approximation: the linear level
// against van Noije & Ernst's closed form, and every level against the moment equations written
// with the symbolic derivation's exact μ2, μ4, μ6 (generated header, an independent route).
#define BOOST_TEST_MODULE theory_sonine_hcs
#include <array>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "molchaos/theory/exact_values.hpp"
#include "molchaos/theory/sonine.hpp"
#include "molchaos/theory/sonine_hcs.hpp"

using namespace molchaos::theory;

namespace {

// μ_p(a2, a3) at b = 0 from the exact terms.
double exact_moment(int d, int p, double eps, double a2, double a3) {
  double sum = 0.0;
  for (const exact::MomentTerm& t : exact::k_moment_terms) {
    if (t.dimension != d || t.moment != p || t.dyad_factor != 3) continue;
    const std::string name = t.term;
    if (name.find('b') != std::string::npos) continue;
    const int i = name == "a2" || name == "a2*a3" ? 1 : name == "a2^2" ? 2 : 0;
    const int j = name == "a3" || name == "a2*a3" ? 1 : name == "a3^2" ? 2 : 0;
    sum += exact::integral(t, eps) * std::pow(a2, i) * std::pow(a3, j);
  }
  return sum;
}

// The residuals F4, F6 of the moment equations (sonine_hcs.hpp) with the exact moments.
std::array<double, 2> exact_residual(int d, double eps, double a2, double a3) {
  const double m2 = exact_moment(d, 2, eps, a2, a3);
  return {exact_moment(d, 4, eps, a2, a3) - (d + 2.0) * (1.0 + a2) * m2,
          exact_moment(d, 6, eps, a2, a3) - 0.75 * (d + 2.0) * (d + 4.0) * (1 + 3 * a2 - a3) * m2};
}

}  // namespace

BOOST_AUTO_TEST_CASE(first_sonine_is_van_noije_ernst) {
  for (int d : {2, 3})
    for (double eps : {0.05, 0.3, 0.7, 0.95}) {
      const HcsSonine h = hcs_sonine_coefficients(d, eps);
      const double exact = a2_first_sonine(d, eps);
      BOOST_TEST(std::abs(h.first_sonine.a2.value - exact) <= 1e-12);
      BOOST_TEST(std::abs(h.first_sonine.a2.value - exact) <=
                 3.0 * h.first_sonine.a2.error + 1e-15);
      BOOST_TEST(h.first_sonine.a3.value == 0.0);
    }
}

BOOST_AUTO_TEST_CASE(nonlinear_levels_solve_the_exact_moment_equations) {
  // |F(x)| with the exact moments at the computed root is bounded by what the root's error allows:
  // |∂F/∂x|·δx with |∂F/∂x| ≤ 10 μ2(0,0) (moments and their a-derivatives are O(μ2)); the a2, a3
  // errors are ~1e-13, so a root off by 1e-9 fails.
  for (int d : {2, 3})
    for (double eps : {0.1, 0.5, 0.9}) {
      const HcsSonine h = hcs_sonine_coefficients(d, eps);
      const double scale = 10.0 * exact_moment(d, 2, eps, 0.0, 0.0);
      const auto f1 = exact_residual(d, eps, h.a2_nonlinear.a2.value, 0.0);
      BOOST_TEST(std::abs(f1[0]) <= scale * (h.a2_nonlinear.a2.error + 1e-15));
      const auto f2 = exact_residual(d, eps, h.a2_a3.a2.value, h.a2_a3.a3.value);
      const double dx = h.a2_a3.a2.error + h.a2_a3.a3.error + 1e-15;
      BOOST_TEST_INFO("d = " << d << ", eps = " << eps << ": " << f2[0] << ", " << f2[1]);
      BOOST_TEST(std::abs(f2[0]) <= scale * dx);
      BOOST_TEST(std::abs(f2[1]) <= 10.0 * scale * dx);
    }
}

BOOST_AUTO_TEST_CASE(linear_a2_a3_solves_the_exact_linearised_equations) {
  // Linearise the exact residual by central differences (quadratic in (a2, a3), so the
  // differences with step h are exact up to rounding ~1e-16/h) and solve the 2×2 system.
  for (int d : {2, 3})
    for (double eps : {0.2, 0.8}) {
      const double h = 1e-4;
      const auto f0 = exact_residual(d, eps, 0, 0);
      const auto fa = exact_residual(d, eps, h, 0), fa_ = exact_residual(d, eps, -h, 0);
      const auto fb = exact_residual(d, eps, 0, h), fb_ = exact_residual(d, eps, 0, -h);
      const double J00 = (fa[0] - fa_[0]) / (2 * h), J01 = (fb[0] - fb_[0]) / (2 * h);
      const double J10 = (fa[1] - fa_[1]) / (2 * h), J11 = (fb[1] - fb_[1]) / (2 * h);
      const double det = J00 * J11 - J01 * J10;
      const double a2 = -(J11 * f0[0] - J01 * f0[1]) / det;
      const double a3 = -(-J10 * f0[0] + J00 * f0[1]) / det;
      const HcsSonine s = hcs_sonine_coefficients(d, eps);
      BOOST_TEST_INFO("d = " << d << ", eps = " << eps);
      BOOST_TEST(std::abs(s.a2_a3_linear.a2.value - a2) <= 1e-10);
      BOOST_TEST(std::abs(s.a2_a3_linear.a3.value - a3) <= 1e-10);
    }
}

BOOST_AUTO_TEST_CASE(elastic_limit_and_cooling_factor) {
  for (int d : {2, 3}) {
    const HcsSonine e = hcs_sonine_coefficients(d, 1.0);
    BOOST_TEST(e.a2_a3.a2.value == 0.0);
    BOOST_TEST(e.a2_a3.mu2_ratio.value == 1.0);
    // Near ε = 1 the four levels converge (a2, a3 = O(1 − ε)).
    const HcsSonine n = hcs_sonine_coefficients(d, 0.999);
    BOOST_TEST(std::abs(n.a2_a3.a2.value - n.first_sonine.a2.value) <= 1e-4);
    // μ2 ratio = 1 + 3/16 a2 + 9/1024 a2² + 1/64 a3 + … (symbolic coefficients) at the solution.
    const HcsSonine m = hcs_sonine_coefficients(d, 0.6);
    const double a2 = m.a2_a3.a2.value, a3 = m.a2_a3.a3.value;
    const double ratio = exact_moment(d, 2, 0.6, a2, a3) / exact_moment(d, 2, 0.6, 0, 0);
    BOOST_TEST(std::abs(m.a2_a3.mu2_ratio.value - ratio) <= m.a2_a3.mu2_ratio.error + 1e-15);
    BOOST_TEST(std::abs(m.a2_a3.A_omega0.value * m.a2_a3.mu2_ratio.value - 1.0) <= 1e-15);
  }
}
