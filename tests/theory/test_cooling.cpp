// Haff's law: prefactors against their derivation, the ODE it solves, Enskog's collision
// frequency, and the paper checks' verdicts.
#define BOOST_TEST_MODULE theory_cooling
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/correlation_range.hpp"
#include "molchaos/theory/paper_checks.hpp"
#include "molchaos/theory/sonine.hpp"

using namespace molchaos::theory;

BOOST_AUTO_TEST_CASE(omega0_closed_forms) {
  const double pi = std::numbers::pi;
  for (double n : {0.05, 0.1}) {
    const double g2d = contact_value_g2_at_density(2, n);
    const double g3d = contact_value_g2_at_density(3, n);
    BOOST_TEST(std::abs(cooling_frequency_omega0(2, n, 1.0) - 0.5 * g2d * n * std::sqrt(pi)) <=
               1e-15);
    BOOST_TEST(std::abs(cooling_frequency_omega0(3, n, 4.0) -
                        2.0 / 3.0 * g3d * n * std::sqrt(4 * pi)) <= 1e-15);
    BOOST_TEST(std::abs(enskog_collision_frequency(2, n, 1.0) - 2 * n * g2d * std::sqrt(pi)) <=
               1e-15);
  }
}

BOOST_AUTO_TEST_CASE(haff_law_solves_the_cooling_equation) {
  // dT/dt = −(2/d) g2 n v0 μ2 T with v0 = √(2T): check with the predicted τ0 at several times.
  for (int d : {2, 3}) {
    CoolingInputs in;
    in.dimension = d;
    in.density = 0.1;
    in.restitution = 0.8;
    in.quadrature.relative_tolerance = 1e-11;
    const CoolingPrediction p = predict_cooling(in);
    for (double t : {0.0, 10.0, 1000.0}) {
      const double T = haff_temperature(t, 1.0, p.tau0.value);
      const double h = 1e-4 * (1.0 + t);
      const double dTdt = (haff_temperature(t + h, 1.0, p.tau0.value) -
                           haff_temperature(t - h, 1.0, p.tau0.value)) /
                          (2 * h);
      const double rhs = -(2.0 / d) * p.g2 * in.density * std::sqrt(2.0 * T) * p.mu2.value * T;
      BOOST_TEST_INFO("d = " << d << ", t = " << t);
      BOOST_TEST(std::abs(dTdt - rhs) <= 1e-7 * std::abs(rhs));
    }
  }
}

BOOST_AUTO_TEST_CASE(A_is_tau0_times_one_minus_eps_squared) {
  CoolingInputs in;
  in.restitution = 0.93;
  in.correlation_b = 0.02;
  const CoolingPrediction p = predict_cooling(in);
  BOOST_TEST(std::abs(p.A.value - p.tau0.value * (1 - 0.93 * 0.93)) <= 1e-12 * p.A.value);
  // Positive b slows cooling (μ2 coefficient of b is negative): A grows.
  BOOST_TEST(p.A.value > p.A_uncorrelated.value);
  // Uncorrelated A = 1/(ω0 (1 + 3/16 a2 + 9/1024 a2²)) exactly.
  const double a2 = a2_first_sonine(2, 0.93);
  const double expect = 1.0 / (p.omega0 * (1 + 3.0 / 16 * a2 + 9.0 / 1024 * a2 * a2));
  BOOST_TEST(std::abs(p.A_uncorrelated.value - expect) <= 1e-9 * expect);
}

// μ2 = (1 − ε²) c_d μ2/μ2(0,0) with c_2 = √(π/2), c_3 = √(2π) (Haff's law's prefactors, as in
// the test above) up to ε = 1 − 2⁻⁵³, where a quadrature at ε itself cancels to noise (it gave a
// negative μ2 there); the same for τ0 = A/(1 − ε²).
BOOST_AUTO_TEST_CASE(mu2_and_tau0_near_the_elastic_limit) {
  for (int d : {2, 3})
    for (double eps : {0.9, 0.99999999999999, 1.0 - std::ldexp(1.0, -53)}) {
      CoolingInputs in;
      in.dimension = d;
      in.restitution = eps;
      const CoolingPrediction p = predict_cooling(in);
      const double one_minus_eps2 = (1.0 - eps) * (1.0 + eps);
      const double c = d == 2 ? std::sqrt(std::numbers::pi / 2) : std::sqrt(2 * std::numbers::pi);
      const double expect = one_minus_eps2 * c * p.mu2_ratio.value;
      BOOST_TEST_INFO("d = " << d << ", eps = " << eps);
      BOOST_TEST(std::abs(p.mu2.value - expect) <= 1e-12 * expect);
      BOOST_TEST(std::abs(p.tau0.value * one_minus_eps2 - p.A.value) <= 1e-12 * p.A.value);
    }
}

BOOST_AUTO_TEST_CASE(elastic_gas_does_not_cool) {
  CoolingInputs in;
  in.restitution = 1.0;
  const CoolingPrediction p = predict_cooling(in);
  BOOST_TEST(std::isinf(p.tau0.value));
  BOOST_TEST(std::abs(p.A.value - 1.0 / p.omega0) <= 1e-9 * p.A.value);  // a2(1) = 0
}

BOOST_AUTO_TEST_CASE(paper_verdicts) {
  QuadratureOptions q;
  q.relative_tolerance = 1e-10;
  const auto table = expand_collision_moment(2, 2, 0.5, k_paper_dyad_factor, q);
  const auto rows = coefficient_checks(table);
  int checked = 0;
  for (const auto& r : rows) {
    if (r.quantity.ends_with(" a2")) {
      BOOST_TEST(r.reproduced.value());
      ++checked;
    }
    if (r.quantity.ends_with(" b")) {
      BOOST_TEST(!r.reproduced.value());
      ++checked;
    }
  }
  BOOST_TEST(checked == 2);
  const auto pre = prefactor_checks(2, q);
  BOOST_TEST(pre.at(0).reproduced.value());   // ½√(2π)
  BOOST_TEST(!pre.at(1).reproduced.value());  // 1/3 printed, 1/2 derived for disks
  const auto pre3 = prefactor_checks(3, q);
  BOOST_TEST(pre3.at(1).reproduced.value());  // 1/3 is the d = 3 value
}

BOOST_AUTO_TEST_CASE(b_range_where_f2_and_mu2_stay_positive) {
  // Upper end: μ2(a2, b) = 0, i.e. b = (1 + 3/16 a2 + 9/1024 a2²)/(3/2 + 21/32 a2 − 93/2048 a2²)
  // (exact coefficients, printed dyad); lower end −4/(κ − 1) = −2 (grazing collisions).
  for (int d : {2, 3})
    for (double eps : {0.3, 0.9}) {
      const double a2 = a2_first_sonine(d, eps);
      const CorrelationRange r = correlation_b_range(d, a2, k_paper_dyad_factor);
      const double upper = (1 + 3.0 / 16 * a2 + 9.0 / 1024 * a2 * a2) /
                           (1.5 + 21.0 / 32 * a2 - 93.0 / 2048 * a2 * a2);
      BOOST_TEST(std::abs(r.upper - upper) <= 1e-12);
      BOOST_TEST(r.lower == -2.0);
      CoolingInputs in;
      in.dimension = d;
      in.restitution = eps;
      in.correlation_b = r.upper;  // μ2 = 0: no finite τ0
      BOOST_CHECK_THROW(predict_cooling(in), std::invalid_argument);
      in.correlation_b = r.lower - 1e-9;
      BOOST_CHECK_THROW(predict_cooling(in), std::invalid_argument);
    }
  // The traceless 2D dyad (κ = 2): lower end −4, upper 4/3 at a2 = 0 (b coefficient −3/4).
  const CorrelationRange t = correlation_b_range(2, 0.0, 2.0);
  BOOST_TEST(t.lower == -4.0);
  BOOST_TEST(std::abs(t.upper - 4.0 / 3.0) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(error_estimates_are_magnitudes) {
  // Over the whole allowed range of b (both signs, up to just below μ2 = 0) and ε, every error
  // estimate of the prediction is non-negative and A, τ0 positive.
  for (int d : {2, 3})
    for (double eps : {0.2, 0.9, 1.0}) {
      const double a2 = a2_first_sonine(d, eps);
      const CorrelationRange r = correlation_b_range(d, a2, k_paper_dyad_factor);
      for (double f : {0.0, 0.3, 0.999, 0.999999}) {
        for (double b : {r.lower * f, r.upper * f}) {
          CoolingInputs in;
          in.dimension = d;
          in.restitution = eps;
          in.correlation_b = b;
          const CoolingPrediction p = predict_cooling(in);
          BOOST_TEST_INFO("d = " << d << ", eps = " << eps << ", b = " << b);
          BOOST_TEST(p.A.value > 0.0);
          BOOST_TEST(p.A.error >= 0.0);
          BOOST_TEST(p.tau0.error >= 0.0);
          BOOST_TEST(p.mu2.error >= 0.0);
          BOOST_TEST(p.mu2_ratio.error >= 0.0);
          BOOST_TEST(p.A_uncorrelated.error >= 0.0);
        }
      }
    }
}

// Near ε = 1, a2 → 0 and b = 0 leave the quadrature errors ∝ |a2| → 0, but 1 + (3/16)a2 + …,
// ω0 and τ0 = A/(1 − ε²) are still rounded: no error may fall below the rounding of its value
// (μ2/μ2(0,0) was 0.9999999 ± 2e-20, A ± 0 at ε = 1). The floors asserted are the fewest
// roundings each value has: the addition in the ratio (u), the product and reciprocal in A (2u),
// the division in τ0 and the two products in μ2 (u, 2u). And a2(1) is +0, not −0.
BOOST_AUTO_TEST_CASE(errors_do_not_fall_below_the_rounding_of_their_value) {
  const double u = std::numeric_limits<double>::epsilon() / 2;
  for (int d : {2, 3})
    for (double eps : {0.999999, 1.0 - 1e-12, 1.0}) {
      CoolingInputs in;
      in.dimension = d;
      in.restitution = eps;
      const CoolingPrediction p = predict_cooling(in);
      BOOST_TEST_INFO("d = " << d << ", eps = " << eps);
      BOOST_TEST(p.A.error >= 2 * u * p.A.value);
      BOOST_TEST(p.A_uncorrelated.error >= 2 * u * p.A_uncorrelated.value);
      if (eps == 1.0) BOOST_TEST(!std::signbit(p.a2));
      if (eps < 1.0) {
        BOOST_TEST(p.mu2_ratio.error >= u * p.mu2_ratio.value);
        BOOST_TEST(p.tau0.error >= u * p.tau0.value);
        BOOST_TEST(p.mu2.error >= 2 * u * p.mu2.value);
      }
    }
  BOOST_TEST(!std::signbit(a2_first_sonine(2, 1.0)));
  BOOST_TEST(!std::signbit(a2_first_sonine(3, 1.0)));
}

// A typed ε = 0.999999 is stored as the nearest double, 5e-17 away: 1 − ε² moves by 5e-11 of
// itself, and μ2 and τ0 with it, a thousand times more than their quadrature errors (7e-20 on μ2
// was stated). The errors cover μ2 and τ0 of the typed decimal, computed here from a long double
// (11 more bits) of the same decimal; A, whose ε-dependence is through a2 alone, does not move.
BOOST_AUTO_TEST_CASE(errors_cover_the_typed_restitution_not_only_the_stored_double) {
  struct Typed {
    double stored;
    long double exact;
  };
  for (int d : {2, 3})
    for (const Typed& e : {Typed{0.999999, 0.999999L}, Typed{0.999999999, 0.999999999L},
                           Typed{0.9, 0.9L}, Typed{0.3, 0.3L}}) {
      CoolingInputs in;
      in.dimension = d;
      in.restitution = e.stored;
      const CoolingPrediction p = predict_cooling(in);
      const long double scale =
          ((1.0L - e.stored) * (1.0L + e.stored)) / ((1.0L - e.exact) * (1.0L + e.exact));
      const double tau0 = static_cast<double>(p.tau0.value * scale);
      const double mu2 = static_cast<double>(p.mu2.value / scale);
      BOOST_TEST_INFO("d = " << d << ", eps = " << e.stored);
      BOOST_TEST(std::abs(tau0 - p.tau0.value) <= p.tau0.error);
      BOOST_TEST(std::abs(mu2 - p.mu2.value) <= p.mu2.error);
      // The term is what the rounding of ε can do, not more: 2ε/(1 − ε²) times half an ulp (2⁻⁵⁴
      // below 1), beside A's relative error of about 1e-14.
      const double shift = 2 * e.stored / (1 - e.stored * e.stored) * std::ldexp(1.0, -54);
      BOOST_TEST(p.tau0.error <= (1e-13 + 2 * shift) * p.tau0.value);
    }
}

// At ε = 1 the nominal end of b, R0/(−R1) = 1/(3/2 ± 8e-14), lay above the exact 2/3: b =
// 0.666666666666668 was taken and gave μ2/μ2(0,0) = 7.8e-16 ± 5.5e-14 and A = 2.7e16 ± 1.9e18.
// A b where μ2 is not positive beyond its error gives no cooling time: refused, and just inside
// the range μ2/μ2(0,0) exceeds its error.
BOOST_AUTO_TEST_CASE(b_range_ends_where_mu2_is_positive_beyond_its_error) {
  CoolingInputs elastic;
  elastic.restitution = 1.0;
  elastic.correlation_b = 0.666666666666668;
  BOOST_CHECK_THROW(predict_cooling(elastic), std::invalid_argument);
  for (int d : {2, 3})
    for (double eps : {0.3, 0.9, 1.0}) {
      const double a2 = a2_first_sonine(d, eps);
      const double a2_error = a2_from_moments(d, eps).error;
      const CorrelationRange r = correlation_b_range(d, a2, k_paper_dyad_factor, {}, a2_error);
      CoolingInputs in;
      in.dimension = d;
      in.restitution = eps;
      in.correlation_b = std::nextafter(r.upper, 0.0);
      const CoolingPrediction p = predict_cooling(in);
      BOOST_TEST_INFO("d = " << d << ", eps = " << eps);
      BOOST_TEST(p.mu2_ratio.value > p.mu2_ratio.error);
      BOOST_TEST(std::isfinite(p.A.value));
      BOOST_TEST(p.A.error < p.A.value);
      // The nominal zero lies upper_error above the end, and the exact 2/3 of a2 = 0 within it.
      BOOST_TEST(r.upper_error > 0.0);
      if (eps == 1.0) BOOST_TEST(std::abs(r.upper + r.upper_error - 2.0 / 3.0) <= r.upper_error);
    }
}

// The range's end printed to the digits its uncertainty supports, cut (never above the end).
BOOST_AUTO_TEST_CASE(range_text_has_the_digits_of_its_error) {
  const CorrelationRange r{-2.0, 0.6666666666666284, 3.8e-14};
  BOOST_TEST(range_text(r) == "[-2, 0.666666666666628)");
  const CorrelationRange coarse{-2.0, 0.67059, 1.2e-3};
  BOOST_TEST(range_text(coarse) == "[-2, 0.6705)");
}

// Eq. (21) is the paper's integral for disks (its Sonine polynomial, Eq. (19), is the 2D one),
// and ω0 of Eq. (24) is built on it: in d = 3 these rows make no claim (they were "NOT
// reproduced"). Eqs. (22) and (10) are in d = 3 form and keep their verdicts; 1/3 carries its
// rounding.
BOOST_AUTO_TEST_CASE(paper_prefactor_rows_for_disks_only_are_not_applicable_in_three_d) {
  QuadratureOptions q;
  const auto pre3 = prefactor_checks(3, q);
  for (std::size_t i : {0u, 2u}) {
    BOOST_TEST_INFO("row " << pre3.at(i).quantity);
    BOOST_TEST(!pre3.at(i).reproduced.has_value());
    BOOST_TEST(pre3.at(i).note.starts_with("not applicable (the paper's "));
  }
  BOOST_TEST(pre3.at(1).reproduced.value());
  BOOST_TEST(pre3.at(3).reproduced.value());
  BOOST_TEST(pre3.at(1).error > 0.0);  // 1/3 is rounded
  const auto pre2 = prefactor_checks(2, q);
  for (const auto& row : pre2) BOOST_TEST(row.reproduced.has_value());
  BOOST_TEST(pre2.at(1).error == 0.0);  // 1/2 is exact
}

// ln t at the collisions where t = τ0(e^x − 1) overflows (x > 709): ln τ0 + x, finite; below,
// the direct log of t.
BOOST_AUTO_TEST_CASE(log_time_is_finite_where_the_time_overflows) {
  const double tau0 = 112.1, omega = 0.1887;
  for (double x : {1e-3, 0.5, 5.0, 50.0, 700.0}) {
    const double direct = std::log(tau0 * std::expm1(x));
    BOOST_TEST(std::abs(log_time_after_collisions(x * omega * tau0, tau0, omega) - direct) <=
               1e-14 * std::abs(direct));
  }
  const double x = 6000.0;
  const double ln_t = log_time_after_collisions(x * omega * tau0, tau0, omega);
  BOOST_TEST(std::isfinite(ln_t));
  BOOST_TEST(std::abs(ln_t - (std::log(tau0) + x)) <= 1e-12 * x);
}
