// Contact averages over colliding pairs to first order in a2 and b (see the header).
#include "molchaos/theory/contact_response.hpp"

#include <cmath>

#include "collision_integrand.hpp"
#include "molchaos/theory/dimension.hpp"
#include "moment_quadrature.hpp"

namespace molchaos::theory {
namespace {

using detail::Observable;

// Term integrals N_T = ∫ W_T X over colliding pairs; indices of the terms 1, a2, b, a2·b.
struct Terms {
  Estimate one, a2, b, a2b;
};

Terms terms_of(int dimension, double dyad_factor, Observable observable,
               const QuadratureOptions& options) {
  const detail::IntegrandSpec spec{dimension, 2, observable, 1.0, dyad_factor, false};
  const detail::TermIntegrals all = detail::integrate_terms(spec, options);
  return {all.terms[0], all.terms[1], all.terms[3], all.terms[4]};
}

Estimate quotient(double numerator, double numerator_error, const Estimate& d0) {
  return {numerator / d0.value, std::abs(numerator_error / d0.value)};
}

// ⟨X⟩ = N(a2, b)/D(a2, b) expanded: x0 = N0/D0, x_a = (N_a − x0 D_a)/D0, x_b likewise,
// x_ab = (N_ab − x0 D_ab − x_a D_b − x_b D_a)/D0. Errors propagated to first order (magnitudes).
ResponseSeries expand_ratio(const Terms& n, const Terms& d) {
  ResponseSeries s;
  s.value = divide(n.one, d.one);
  const double x0 = s.value.value, e0 = s.value.error;
  s.d_a2 = quotient(n.a2.value - x0 * d.a2.value,
                    n.a2.error + std::abs(x0) * d.a2.error + e0 * std::abs(d.a2.value), d.one);
  s.d_b = quotient(n.b.value - x0 * d.b.value,
                   n.b.error + std::abs(x0) * d.b.error + e0 * std::abs(d.b.value), d.one);
  const double xa = s.d_a2.value, xb = s.d_b.value;
  s.d_a2b = quotient(n.a2b.value - x0 * d.a2b.value - xa * d.b.value - xb * d.a2.value,
                     n.a2b.error + std::abs(x0) * d.a2b.error + e0 * std::abs(d.a2b.value) +
                         std::abs(xa) * d.b.error + s.d_a2.error * std::abs(d.b.value) +
                         std::abs(xb) * d.a2.error + s.d_b.error * std::abs(d.a2.value),
                     d.one);
  // The quotient's own relative error on top (D0's error).
  for (Estimate* e : {&s.d_a2, &s.d_b, &s.d_a2b})
    e->error += std::abs(e->value) * d.one.relative_error();
  return s;
}

// A series divided by a constant reference (exact division of each coefficient).
ResponseSeries scaled(ResponseSeries s, const Estimate& reference) {
  for (Estimate* e : {&s.value, &s.d_a2, &s.d_b, &s.d_a2b}) *e = divide(*e, reference);
  return s;
}

}  // namespace

ContactResponse contact_response(int dimension, double dyad_factor,
                                 const QuadratureOptions& options) {
  require_dimension(dimension);
  ContactResponse out;
  out.dimension = dimension;
  out.dyad_factor = dyad_factor;
  const Terms one = terms_of(dimension, dyad_factor, Observable::one, options);
  out.normal_product =
      expand_ratio(terms_of(dimension, dyad_factor, Observable::normal_product, options), one);
  out.velocity_product =
      expand_ratio(terms_of(dimension, dyad_factor, Observable::velocity_product, options), one);
  out.dyad = expand_ratio(terms_of(dimension, dyad_factor, Observable::dyad, options), one);
  // ω ∝ ∫ Θ|c12·e| f̃f̃[1 + bD]: the series of J_1 itself, over its value at a2 = b = 0.
  ResponseSeries omega{one.one, one.a2, one.b, one.a2b};
  out.collision_frequency_ratio = scaled(omega, one.one);
  const ResponseSeries dissipation = expand_ratio(
      terms_of(dimension, dyad_factor, Observable::normal_speed_squared, options), one);
  out.dissipation_ratio = scaled(dissipation, dissipation.value);
  return out;
}

}  // namespace molchaos::theory
