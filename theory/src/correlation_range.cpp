// The admissible range of the correlation coefficient b (see the header and doc/theory.md §6).
#include "molchaos/theory/correlation_range.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "molchaos/theory/dimension.hpp"

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
  if (!(dyad_factor > 1.0))
    throw std::invalid_argument("dyad_factor: must exceed 1 (the dyad κ ee − U)");
  CorrelationRange range{-4.0 / (dyad_factor - 1.0), std::numeric_limits<double>::infinity()};
  // μ2/μ2(0,0) = R0 + b R1 (linear in b; ε-independent, taken at ε = 1/2).
  const ExpansionTable mu2 = expand_collision_moment(dimension, 2, 0.5, dyad_factor, options);
  const double r0 = mu2.ratio(a2, 0.0);
  clip_positive(r0, mu2.ratio(a2, 1.0) - r0, range);
  // Collision rate ∝ J_1 + b J_D.
  const ContactIntegrals contact = contact_integrals(dimension, a2, dyad_factor, options);
  clip_positive(contact.one.value, contact.dyad.value, range);
  return range;
}

void require_correlation_b(int dimension, double a2, double dyad_factor, double b,
                           const QuadratureOptions& options) {
  const CorrelationRange r = correlation_b_range(dimension, a2, dyad_factor, options);
  if (!(b >= r.lower && b < r.upper)) {
    std::ostringstream msg;
    msg.precision(6);
    msg << "correlation_b: value " << b << " is outside the allowed range [" << r.lower << ", "
        << r.upper << ") where the ansatz's f2 (grazing collisions, collision rate) and μ2 stay "
        << "positive (d = " << dimension << ", a2 = " << a2 << ", dyad factor " << dyad_factor
        << ")";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace molchaos::theory
