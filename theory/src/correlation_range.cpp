// The admissible range of the correlation coefficient b (see the header and doc/theory.md §6).
#include "molchaos/theory/correlation_range.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "collision_integrand.hpp"
#include "molchaos/theory/dimension.hpp"
#include "moment_quadrature.hpp"

namespace molchaos::theory {
namespace {

// A quantity linear in b, value0 + b·slope, known within error0 + |b|·slope_error: the b where it
// stays above its error (positive beyond doubt). Where it is not, a cooling time or collision
// rate built on it could be of either sign. The end of the range lies where value and error
// meet, (value0 − error0)/(∓slope + slope_error); the distance to the nominal zero −value0/slope
// is the uncertainty of that zero.
void clip_distinguishable(double value0, double error0, double slope, double slope_error,
                          CorrelationRange& range) {
  const double margin = value0 - error0;
  if (slope < 0.0) {
    const double end = margin / (-slope + slope_error);
    if (end < range.upper) {
      range.upper = end;
      range.upper_error = value0 / -slope - end;
    }
  }
  if (slope > 0.0) range.lower = std::max(range.lower, -margin / (slope + slope_error));
}

}  // namespace

CorrelationRange correlation_b_range(int dimension, double a2, double dyad_factor,
                                     const QuadratureOptions& options, double a2_error) {
  require_dimension(dimension);
  return correlation_b_range(expand_collision_moment(dimension, 2, 0.5, dyad_factor, options), a2,
                             options, a2_error);
}

CorrelationRange correlation_b_range(const ExpansionTable& mu2, double a2,
                                     const QuadratureOptions& options, double a2_error) {
  const double kappa = mu2.dyad_factor;
  if (!(kappa > 1.0)) throw std::invalid_argument("dyad_factor: must exceed 1 (the dyad κ ee − U)");
  if (mu2.moment != 2) throw std::invalid_argument("mu2_table: must be the table of μ2");
  CorrelationRange range{-4.0 / (kappa - 1.0), std::numeric_limits<double>::infinity(), 0.0};
  // μ2/μ2(0,0) = R0 + b R1 (linear in b), with the error of ratio_estimate (coefficients,
  // rounding, a2's uncertainty), e0 + |b| e1 to first order: e1 from b = ±1, whichever is larger.
  const Estimate at0 = mu2.ratio_estimate(PairShape{a2, 0.0, 0.0}, a2_error);
  const Estimate up = mu2.ratio_estimate(PairShape{a2, 0.0, 1.0}, a2_error);
  const Estimate down = mu2.ratio_estimate(PairShape{a2, 0.0, -1.0}, a2_error);
  const double e1 = std::max({up.error - at0.error, down.error - at0.error, 0.0});
  clip_distinguishable(at0.value, at0.error, up.value - at0.value, e1, range);
  // Collision rate ∝ J_1 + b J_D: the terms 1, a2, a2² of ∫ f̃f̃ (1 + bD) with observable 1.
  const detail::IntegrandSpec spec{mu2.dimension, 2, detail::Observable::one, 1.0, kappa, false};
  const detail::TermIntegrals J = detail::integrate_terms(spec, options);
  // J_1 and J_D at a2 from the terms 1, a2, a2², with their errors, a2's uncertainty through
  // ∂/∂a2, and the rounding of the sum (a2², three products, two additions: 6u).
  auto at_a2 = [&](std::size_t first) {
    const Estimate& c0 = J.terms[first];
    const Estimate& c1 = J.terms[first + 1];
    const Estimate& c2 = J.terms[first + 2];
    const double value = c0.value + a2 * c1.value + a2 * a2 * c2.value;
    const double magnitude =
        std::abs(c0.value) + std::abs(a2 * c1.value) + std::abs(a2 * a2 * c2.value);
    return Estimate{value, c0.error + std::abs(a2) * c1.error + a2 * a2 * c2.error +
                               std::abs(c1.value + 2.0 * a2 * c2.value) * a2_error +
                               rounding_bound(magnitude, 6.0)};
  };
  const Estimate j1 = at_a2(0), jd = at_a2(3);
  clip_distinguishable(j1.value, j1.error, jd.value, jd.error, range);
  return range;
}

std::string range_text(const CorrelationRange& r, int significant_digits) {
  std::string upper = exact_text(r.upper);
  const bool shortened = r.upper_error > 0.0 || significant_digits < 17;
  if (shortened && std::isfinite(r.upper) && r.upper != 0.0) {
    // Decimals down to the second significant digit of the bound's uncertainty (the errors are
    // printed with two), at most significant_digits, cut rather than rounded: every b below the
    // printed end is accepted.
    int decimals =
        significant_digits - 1 - static_cast<int>(std::floor(std::log10(std::abs(r.upper))));
    if (r.upper_error > 0.0)
      decimals = std::min(decimals, 1 - static_cast<int>(std::floor(std::log10(r.upper_error))));
    decimals = std::clamp(decimals, 0, 17);
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals + 3, r.upper);
    upper.assign(text, std::strlen(text) - 3);
    if (upper.back() == '.') upper.pop_back();
  }
  std::string out("[");
  out.append(exact_text(r.lower)).append(", ").append(upper).append(")");
  return out;
}

void require_correlation_b(const ExpansionTable& mu2, double a2, double b,
                           const QuadratureOptions& options, double a2_error) {
  const CorrelationRange r = correlation_b_range(mu2, a2, options, a2_error);
  if (!(b >= r.lower && b < r.upper)) {
    std::ostringstream msg;
    msg.precision(6);
    msg << "correlation_b: value " << exact_text(b) << " is outside the allowed range "
        << range_text(r)
        << " where the ansatz's f2 (grazing collisions, collision rate) stays positive and μ2 "
        << "is positive beyond its error (a cooling time exists) (d = " << mu2.dimension
        << ", a2 = " << a2 << ", dyad factor " << mu2.dyad_factor << ")";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace molchaos::theory
