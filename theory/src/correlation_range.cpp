// The admissible range of the correlation coefficient b (see the header and doc/theory.md §6).
#include "molchaos/theory/correlation_range.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "collision_integrand.hpp"
#include "molchaos/theory/dimension.hpp"
#include "moment_quadrature.hpp"

namespace molchaos::theory {
namespace {

// The largest b > 0 (and smallest b < 0) at which value0 + b·slope stays positive.
void clip_positive(double value0, double slope, CorrelationRange& range) {
  if (slope < 0.0) range.upper = std::min(range.upper, value0 / -slope);
  if (slope > 0.0) range.lower = std::max(range.lower, -value0 / slope);
}

}  // namespace

CorrelationRange correlation_b_range(int dimension, double a2, double dyad_factor,
                                     const QuadratureOptions& options) {
  require_dimension(dimension);
  return correlation_b_range(expand_collision_moment(dimension, 2, 0.5, dyad_factor, options), a2,
                             options);
}

CorrelationRange correlation_b_range(const ExpansionTable& mu2, double a2,
                                     const QuadratureOptions& options) {
  const double kappa = mu2.dyad_factor;
  if (!(kappa > 1.0)) throw std::invalid_argument("dyad_factor: must exceed 1 (the dyad κ ee − U)");
  if (mu2.moment != 2) throw std::invalid_argument("mu2_table: must be the table of μ2");
  CorrelationRange range{-4.0 / (kappa - 1.0), std::numeric_limits<double>::infinity()};
  // μ2/μ2(0,0) = R0 + b R1 (linear in b).
  const double r0 = mu2.ratio(a2, 0.0);
  clip_positive(r0, mu2.ratio(a2, 1.0) - r0, range);
  // Collision rate ∝ J_1 + b J_D: the terms 1, a2, a2² of ∫ f̃f̃ (1 + bD) with observable 1.
  const detail::IntegrandSpec spec{mu2.dimension, 2, detail::Observable::one, 1.0, kappa, false};
  const detail::TermIntegrals J = detail::integrate_terms(spec, options);
  const double j1 = J.terms[0].value + a2 * J.terms[1].value + a2 * a2 * J.terms[2].value;
  const double jd = J.terms[3].value + a2 * J.terms[4].value + a2 * a2 * J.terms[5].value;
  clip_positive(j1, jd, range);
  return range;
}

void require_correlation_b(const ExpansionTable& mu2, double a2, double b,
                           const QuadratureOptions& options) {
  const CorrelationRange r = correlation_b_range(mu2, a2, options);
  if (!(b >= r.lower && b < r.upper)) {
    std::ostringstream msg;
    msg.precision(6);
    msg << "correlation_b: value " << exact_text(b) << " is outside the allowed range ["
        << exact_text(r.lower) << ", " << exact_text(r.upper) << ") where the ansatz's f2 (grazing collisions, collision rate) and μ2 stay "
        << "positive (d = " << mu2.dimension << ", a2 = " << a2 << ", dyad factor "
        << mu2.dyad_factor << ")";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace molchaos::theory
