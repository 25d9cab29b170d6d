// A number with its error estimate: what every numerical result of molchaos carries.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace molchaos::theory {

/// value ± error. For a quadrature `error` is the integrator's absolute error estimate; for an
/// exact closed form it is 0.
struct Estimate {
  double value = 0.0;
  double error = 0.0;

  [[nodiscard]] double relative_error() const {
    return value != 0.0 ? error / std::abs(value) : error;
  }
};

/// Unit roundoff u = 2⁻⁵³: an IEEE operation (+ − × ÷ √) on exact operands is off by at most u
/// relative to its exact result; libm's pow, exp and log by under one ulp (2u).
inline constexpr double k_unit_roundoff = std::numeric_limits<double>::epsilon() / 2.0;

/// First-order bound on the rounding of a value produced by a chain of `roundings` operations,
/// each off by at most u relative: roundings · u · |value|. The floor under every error estimate
/// of a computed (not exact) number: no error bar can be finer than the arithmetic that made it.
inline double rounding_bound(double value, double roundings) {
  return roundings * k_unit_roundoff * std::abs(value);
}

/// Half the spacing of the doubles around x (the wider side): how far the decimal a user typed
/// may lie from the double x it was stored as. A result's error covers the typed input only if it
/// adds this, times the result's sensitivity to x.
inline double input_rounding(double x) {
  const double inf = std::numeric_limits<double>::infinity();
  return 0.5 * std::max(std::nextafter(x, inf) - x, x - std::nextafter(x, -inf));
}

/// Quotient with first-order propagation of the relative errors.
inline Estimate divide(const Estimate& num, const Estimate& den) {
  const double q = num.value / den.value;
  return {q, std::abs(q) * (num.relative_error() + den.relative_error())};
}

}  // namespace molchaos::theory
