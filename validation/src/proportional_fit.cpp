// Effective-variance fit of y = k x (see proportional_fit.hpp).
#include "molchaos/validation/proportional_fit.hpp"

#include <cmath>
#include <stdexcept>

#include "molchaos/validation/pair_correlations.hpp"

namespace molchaos::validation {
namespace {

double chi2_at(const std::vector<Measurement>& y, const std::vector<Measurement>& x, double k) {
  double chi2 = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double var = y[i].error * y[i].error + k * k * x[i].error * x[i].error;
    if (var > 0.0) chi2 += std::pow(y[i].value - k * x[i].value, 2) / var;
  }
  return chi2;
}

}  // namespace

ProportionalFit fit_proportional(const std::vector<Measurement>& y,
                                 const std::vector<Measurement>& x) {
  if (y.size() != x.size())
    throw std::invalid_argument("fit_proportional: y and x differ in length");
  ProportionalFit f;
  // Fixed point of the weighted normal equation k = Σ w y x / Σ w x², w = 1/(σy² + k² σx²): the
  // weights change slowly with k, so a few dozen passes converge to round-off.
  double k = 1.0, sxx = 0.0;
  for (int pass = 0; pass < 100; ++pass) {
    double sxy = 0.0;
    sxx = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double var = y[i].error * y[i].error + k * k * x[i].error * x[i].error;
      if (!(var > 0.0)) continue;
      sxy += y[i].value * x[i].value / var;
      sxx += x[i].value * x[i].value / var;
    }
    if (!(sxx > 0.0)) return f;
    const double next = sxy / sxx;
    const bool converged = std::abs(next - k) <= 1e-14 * std::abs(next);
    k = next;
    if (converged) break;
  }
  for (std::size_t i = 0; i < y.size(); ++i)
    if (y[i].error > 0.0 || x[i].error > 0.0) ++f.points;
  f.ratio = {k, 1.0 / std::sqrt(sxx)};
  f.chi2_of_fit = chi2_at(y, x, k);
  f.chi2_of_equal = chi2_at(y, x, 1.0);
  f.p_equal = chi_square_p_value(f.chi2_of_equal, f.points);
  return f;
}

}  // namespace molchaos::validation
