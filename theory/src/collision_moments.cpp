// The collision moments μ_p and their expansion (see the header for the integral and its
// reduction; the quadratures are in moment_quadrature.cpp).
#include "molchaos/theory/collision_moments.hpp"

#include <cmath>
#include <stdexcept>

#include "collision_integrand.hpp"
#include "molchaos/theory/dimension.hpp"
#include "moment_quadrature.hpp"

namespace molchaos::theory {
namespace {

using detail::IntegrandSpec;
using detail::k_term_count;
using detail::k_terms;
using detail::Observable;

void require_moment(int p) {
  if (p != 2 && p != 4 && p != 6)
    throw std::invalid_argument("moment: value " + std::to_string(p) +
                                " is not allowed; allowed values 2, 4 or 6");
}

double monomial(const detail::TermPowers& t, const PairShape& s) {
  return std::pow(s.a2, t.a2) * std::pow(s.a3, t.a3) * std::pow(s.b, t.b);
}

detail::TermSums monomials(const PairShape& s) {
  detail::TermSums m{};
  for (std::size_t t = 0; t < k_term_count; ++t) m[t] = monomial(k_terms[t], s);
  return m;
}

}  // namespace

int exact_hermite_order(int p) {
  // Degree in each C component: S2·S2·D contributes ≤ 4 + 4 + 2, Δ(c^p) ≤ p. A rule of order n
  // integrates degree 2n − 1 exactly.
  return exact_gauss_order(10 + p);
}

Estimate collision_moment(int dimension, int p, double restitution, const PairShape& shape,
                          double dyad_factor, const QuadratureOptions& options) {
  require_dimension(dimension);
  require_moment(p);
  require_restitution(restitution);
  IntegrandSpec spec{dimension,   p,           Observable::moment_change,
                     restitution, dyad_factor, shape.a3 != 0.0};
  return detail::integrate_combination(spec, monomials(shape), options);
}

const ExpansionTerm& ExpansionTable::term(const std::string& name) const {
  for (const auto& t : terms)
    if (t.name == name) return t;
  throw std::out_of_range("no expansion term named '" + name + "'");
}

double ExpansionTable::ratio(double a2, double b) const { return ratio(PairShape{a2, 0.0, b}); }

double ExpansionTable::ratio(const PairShape& shape) const { return ratio_estimate(shape).value; }

Estimate ExpansionTable::ratio_estimate(const PairShape& s, double a2_error) const {
  Estimate r{1.0, 0.0};
  // An uncertain a2 moves the ratio by |∂ratio/∂a2|·δa2 (the polynomial differentiated).
  double slope_a2 = 0.0;
  // The rounding of the sum 1 + Σ c·m itself, which the coefficients' errors (∝ |m|) miss: they
  // vanish with a2 and b (ε → 1), while 1 + … is still rounded. A non-zero term costs its
  // monomial (pow(x, k), under 2u for k ≥ 2, exact for k ≤ 1; two products), the product with its
  // coefficient (u of |c·m|) and the addition (u of the partial sum); a zero term is exact, so
  // the ratio at a2 = a3 = b = 0 is 1 ± 0.
  double rounding = 0.0;
  for (const auto& t : terms) {
    const double m =
        std::pow(s.a2, t.a2_power) * std::pow(s.a3, t.a3_power) * std::pow(s.b, t.b_power);
    const double x = t.coefficient.value * m;
    r.value += x;
    r.error += t.coefficient.error * std::abs(m);
    if (t.a2_power > 0)
      slope_a2 += t.coefficient.value * t.a2_power * std::pow(s.a2, t.a2_power - 1) *
                  std::pow(s.a3, t.a3_power) * std::pow(s.b, t.b_power);
    if (x != 0.0) {
      const int pows = (t.a2_power > 1) + (t.a3_power > 1) + (t.b_power > 1);
      rounding += rounding_bound(x, 2.0 * pows + 3.0) + rounding_bound(r.value, 1.0);
    }
  }
  r.error += rounding + std::abs(slope_a2) * a2_error;
  return r;
}

ExpansionTable expand_collision_moment(int dimension, int p, double restitution, double dyad_factor,
                                       const QuadratureOptions& options, SonineTerms which) {
  require_dimension(dimension);
  require_moment(p);
  require_restitution(restitution);
  if (restitution == 1.0)
    throw std::invalid_argument(
        "restitution: μ_p vanishes at ε = 1 for the Maxwellian, so its coefficients are "
        "undefined; allowed range (0, 1)");
  const bool with_a3 = which == SonineTerms::a2_a3;
  ExpansionTable table;
  table.dimension = dimension;
  table.moment = p;
  table.restitution = restitution;
  table.dyad_factor = dyad_factor;
  table.relative_tolerance = options.relative_tolerance;
  const IntegrandSpec spec{dimension,   p,           Observable::moment_change,
                           restitution, dyad_factor, with_a3};
  const detail::TermIntegrals all = detail::integrate_terms(spec, options);
  table.base = all.terms[0];
  table.integrand_evaluations = all.evaluations;
  const std::size_t used = with_a3 ? k_term_count : detail::k_a2_term_count;
  for (std::size_t t = 1; t < used; ++t) {
    const auto& powers = k_terms[t];
    ExpansionTerm term;
    term.name = powers.name;
    term.a2_power = powers.a2;
    term.b_power = powers.b;
    term.a3_power = powers.a3;
    term.integral = all.terms[t];
    term.coefficient = divide(all.terms[t], table.base);
    table.terms.push_back(term);
  }
  return table;
}

Estimate a2_from_moments(int dimension, double restitution, const QuadratureOptions& options) {
  require_dimension(dimension);
  require_restitution(restitution);
  if (restitution == 1.0) return {0.0, 0.0};  // elastic: the Maxwellian is exact
  const ExpansionTable mu2 = expand_collision_moment(dimension, 2, restitution, 3.0, options);
  const ExpansionTable mu4 = expand_collision_moment(dimension, 4, restitution, 3.0, options);
  // μ_p ≈ A_p (1 + k_p a2): (A4 + A4 k4 a2) = (d+2)(1 + a2)(A2 + A2 k2 a2), linear in a2.
  const double d2 = dimension + 2.0;
  const Estimate& A2 = mu2.base;
  const Estimate& A4 = mu4.base;
  const Estimate& k2 = mu2.term("a2").coefficient;
  const Estimate& k4 = mu4.term("a2").coefficient;
  const double num = A4.value - d2 * A2.value;
  const double den = d2 * A2.value * (1.0 + k2.value) - A4.value * k4.value;
  const double a2 = num / den;
  // First-order propagation of the (independent) quadrature errors.
  const double dnum = A4.error + d2 * A2.error;
  const double dden = d2 * (A2.error * std::abs(1.0 + k2.value) + std::abs(A2.value) * k2.error) +
                      A4.error * std::abs(k4.value) + std::abs(A4.value) * k4.error;
  return {a2, (dnum + std::abs(a2) * dden) / std::abs(den)};
}

ContactIntegrals contact_integrals(int dimension, double a2, double dyad_factor,
                                   const QuadratureOptions& options) {
  require_dimension(dimension);
  ContactIntegrals out;
  const detail::TermSums m = monomials(PairShape{a2, 0.0, 0.0});
  IntegrandSpec spec{dimension, 2, Observable::one, 1.0, dyad_factor, false};
  out.one = detail::integrate_combination(spec, m, options);
  spec.observable = Observable::dyad;
  out.dyad = detail::integrate_combination(spec, m, options);
  // ∫ f̃f̃ D² is the b term of ∫ f̃f̃ (1 + bD) D.
  detail::TermSums mb{};
  for (std::size_t t = 0; t < k_term_count; ++t)
    if (k_terms[t].b == 1 && k_terms[t].a3 == 0) mb[t] = std::pow(a2, k_terms[t].a2);
  out.dyad_squared = detail::integrate_combination(spec, mb, options);
  return out;
}

Estimate ContactIntegrals::mean_dyad(double b) const {
  const double num = dyad.value + b * dyad_squared.value;
  const double den = one.value + b * dyad.value;
  const double err = (dyad.error + std::abs(b) * dyad_squared.error) / std::abs(den) +
                     std::abs(num / (den * den)) * (one.error + std::abs(b) * dyad.error);
  return {num / den, err};
}

Estimate ContactIntegrals::b_from_mean_dyad(double m, double m_error) const {
  // m = (J_D + b J_DD)/(J_1 + b J_D)  ⇒  b = (m J_1 − J_D)/(J_DD − m J_D).
  const double num = m * one.value - dyad.value;
  const double den = dyad_squared.value - m * dyad.value;
  const double b = num / den;
  const double dbdm = (one.value * den + num * dyad.value) / (den * den);
  const double quad = (std::abs(m) * one.error + dyad.error +
                       std::abs(b) * (dyad_squared.error + std::abs(m) * dyad.error)) /
                      std::abs(den);
  return {b, std::abs(dbdm) * m_error + quad};
}

}  // namespace molchaos::theory
