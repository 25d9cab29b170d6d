// A number with its error estimate: what every numerical result of molchaos carries.
#pragma once

#include <cmath>

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

/// Quotient with first-order propagation of the relative errors.
inline Estimate divide(const Estimate& num, const Estimate& den) {
  const double q = num.value / den.value;
  return {q, std::abs(q) * (num.relative_error() + den.relative_error())};
}

}  // namespace molchaos::theory
