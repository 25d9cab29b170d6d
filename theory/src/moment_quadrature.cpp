// Gauss product rules and nested adaptive QAGIU over the relative velocity (see the header).
//
// After the exact centre-of-mass sum the integrand at relative velocity g = (−u, ρ, 0) is a
// polynomial Q in u² and ρ² (even in u and in ρ by the reflections (C, g) → (−C, −g) and
// (C_y, g_y) → (−C_y, −g_y)) times u e^{−u²/2} ρ^{d−2} e^{−ρ²/2}. With s = u²/2 and t = ρ²/2,
//     ∫_0^∞ du u e^{−u²/2} ∫ d^{d−1}g⊥ e^{−g⊥²/2} Q = c_d ∫_0^∞ ds e^{−s} ∫_0^∞ dt t^{(d−3)/2}
//     e^{−t} Q,
// c_2 = √2 (g_y over the whole line), c_3 = 2π (polar angle about e): Gauss–Laguerre in s and
// generalised Gauss–Laguerre (α = (d − 3)/2) in t, exact for the polynomial degree of Q.
#include "moment_quadrature.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "molchaos/theory/dimension.hpp"

namespace molchaos::theory::detail {
namespace {

// μ_p carries −½ (paper Eq. (20)); the contact integrals are plain sums over colliding pairs.
// Both carry |S^{d−1}| (e fixed along x) and π^{−d} (the Maxwellians' normalisation).
double prefactor(const IntegrandSpec& spec) {
  const double sign_half = spec.observable == Observable::moment_change ? -0.5 : 1.0;
  return sign_half * unit_sphere_area(spec.dimension) / std::pow(std::numbers::pi, spec.dimension);
}

struct GaussPass {
  TermSums sums{}, magnitudes{};
  std::size_t evaluations = 0;
};

GaussPass gauss_pass(const IntegrandSpec& spec, int hermite_order, int laguerre_order) {
  const CentreOfMassSum centre(spec, hermite_order);
  const GaussRule normal = gauss_laguerre_rule(laguerre_order, 0.0);
  const GaussRule tangential = gauss_laguerre_rule(laguerre_order, 0.5 * (spec.dimension - 3));
  const double measure = spec.dimension == 2 ? std::numbers::sqrt2 : 2.0 * std::numbers::pi;
  GaussPass pass;
  for (std::size_t i = 0; i < normal.nodes.size(); ++i) {
    const double u = std::sqrt(2.0 * normal.nodes[i]);
    for (std::size_t j = 0; j < tangential.nodes.size(); ++j) {
      const double rho = std::sqrt(2.0 * tangential.nodes[j]);
      centre.accumulate(u, rho, measure * normal.weights[i] * tangential.weights[j], pass.sums,
                        pass.magnitudes);
      ++pass.evaluations;
    }
  }
  return pass;
}

// The exact rule and one of the next order: both integrate the polynomial exactly, so their
// difference measures what rounding (or, with orders set too low on purpose, truncation) leaves.
// The rounding bound degree·(order + 1)·DBL_EPSILON·Σ|w f|: a Golub–Welsch node carries an
// absolute error of order (order)·ε times the largest node (the norm of the Jacobi matrix), which
// a polynomial of the given degree amplifies up to (degree)-fold relative to its value.
TermIntegrals integrate_terms_gauss(const IntegrandSpec& spec, const QuadratureOptions& o) {
  const int degree = polynomial_degree(spec);
  const int n_c = o.hermite_order > 0 ? o.hermite_order : exact_gauss_order(degree);
  const int n_l = o.laguerre_order > 0 ? o.laguerre_order : exact_gauss_order(degree / 2);
  const GaussPass low = gauss_pass(spec, n_c, n_l);
  const GaussPass high = gauss_pass(spec, n_c + 1, n_l + 1);
  const double scale = prefactor(spec);
  TermIntegrals out;
  out.evaluations = low.evaluations + high.evaluations;
  const double rounding = degree * (std::max(n_c, n_l) + 2.0) * DBL_EPSILON;
  for (std::size_t t = 0; t < k_term_count; ++t) {
    const double error = std::abs(high.sums[t] - low.sums[t]) + rounding * high.magnitudes[t];
    out.terms[t] = {scale * high.sums[t], std::abs(scale) * error};
  }
  return out;
}

// ---- adaptive (nested GSL QAGIU) -------------------------------------------------------------

using Workspace =
    std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)>;

Workspace make_workspace(std::size_t n) {
  Workspace w(gsl_integration_workspace_alloc(n), &gsl_integration_workspace_free);
  if (!w) throw std::runtime_error("GSL integration workspace: allocation failed");
  return w;
}

// GSL_EROUND (roundoff prevents the requested tolerance) still returns a usable result with an
// honest error estimate; every other failure is an error.
void check_status(int status, const char* where) {
  if (status != GSL_SUCCESS && status != GSL_EROUND)
    throw std::runtime_error(std::string(where) + ": " + gsl_strerror(status));
}

// Absolute accuracy floor, relative to the O(1) size of the moments: without it an integral that
// vanishes (μ2 at ε = 1, an inner integral at a sign change) could never meet a relative
// tolerance. The reported error estimate stays honest either way.
constexpr double k_absolute_floor = 1e-3;

// The outer integrand is itself an adaptive integral over the tangential speed; its error
// estimate err(u) is kept so that ∫ err(u) du can be added to the outer error estimate.
struct NestedState {
  const CentreOfMassSum* centre;
  const TermSums* multipliers;
  gsl_integration_workspace* inner_ws;
  std::size_t limit;
  double inner_tol;
  double u;
  double last_error;
  std::size_t evaluations;
};

double integrand_at(NestedState* s, double rho) {
  TermSums sums{}, magnitudes{};
  s->centre->accumulate(s->u, rho, 1.0, sums, magnitudes);
  ++s->evaluations;
  double sum = 0.0;
  for (std::size_t t = 0; t < k_term_count; ++t) sum += (*s->multipliers)[t] * sums[t];
  const int d = s->centre->spec().dimension;
  const double tangential_measure = d == 2 ? 2.0 : 2.0 * std::numbers::pi * rho;
  return s->u * std::exp(-0.5 * (s->u * s->u + rho * rho)) * tangential_measure * sum;
}

double inner_integral(double u, NestedState* s) {
  s->u = u;
  gsl_function f;
  f.params = s;
  f.function = [](double rho, void* q) { return integrand_at(static_cast<NestedState*>(q), rho); };
  double value = 0.0, error = 0.0;
  check_status(gsl_integration_qagiu(&f, 0.0, k_absolute_floor * s->inner_tol, s->inner_tol,
                                     s->limit, s->inner_ws, &value, &error),
               "inner (tangential) quadrature");
  s->last_error = error;
  return value;
}

Estimate integrate_adaptive(const IntegrandSpec& spec, const TermSums& multipliers,
                            const QuadratureOptions& options, std::size_t& evaluations) {
  gsl_set_error_handler_off();
  const int n_c = options.hermite_order > 0 ? options.hermite_order
                                            : exact_gauss_order(polynomial_degree(spec));
  const CentreOfMassSum centre(spec, n_c);
  const double outer_tol = options.relative_tolerance;
  const double inner_tol = std::max(0.1 * outer_tol, 1e-14);
  Workspace outer_ws = make_workspace(options.workspace_intervals);
  Workspace inner_ws = make_workspace(options.workspace_intervals);
  NestedState state{
      &centre, &multipliers, inner_ws.get(), options.workspace_intervals, inner_tol, 0.0, 0.0, 0};
  gsl_function outer;
  outer.params = &state;
  outer.function = [](double u, void* p) {
    return inner_integral(u, static_cast<NestedState*>(p));
  };
  double value = 0.0, error = 0.0;
  check_status(gsl_integration_qagiu(&outer, 0.0, k_absolute_floor * outer_tol, outer_tol,
                                     options.workspace_intervals, outer_ws.get(), &value, &error),
               "outer (normal) quadrature");
  // ∫ err_inner(u) du, to 10 % (it is an error bar, not a result).
  gsl_function outer_error;
  outer_error.params = &state;
  outer_error.function = [](double u, void* p) {
    auto* s = static_cast<NestedState*>(p);
    inner_integral(u, s);
    return s->last_error;
  };
  double inner_error = 0.0, inner_error_error = 0.0;
  check_status(gsl_integration_qagiu(&outer_error, 0.0, 0.0, 0.1, options.workspace_intervals,
                                     outer_ws.get(), &inner_error, &inner_error_error),
               "inner error estimate");
  evaluations += state.evaluations;
  const double scale = prefactor(spec);
  return {scale * value, std::abs(scale) * (error + inner_error + inner_error_error)};
}

void require_tolerance(const QuadratureOptions& options) {
  if (options.method == QuadratureMethod::adaptive &&
      !(options.relative_tolerance >= k_min_relative_tolerance &&
        options.relative_tolerance <= k_max_relative_tolerance))
    throw std::invalid_argument("relative_tolerance: value " +
                                std::to_string(options.relative_tolerance) +
                                " is outside the allowed range [1e-13, 0.01]");
}

}  // namespace

TermIntegrals integrate_terms(const IntegrandSpec& spec, const QuadratureOptions& options) {
  require_tolerance(options);
  if (options.method == QuadratureMethod::gauss) return integrate_terms_gauss(spec, options);
  TermIntegrals out;
  const std::size_t used = spec.with_a3 ? k_term_count : k_a2_term_count;
  for (std::size_t t = 0; t < used; ++t) {
    TermSums unit{};
    unit[t] = 1.0;
    out.terms[t] = integrate_adaptive(spec, unit, options, out.evaluations);
  }
  return out;
}

Estimate integrate_combination(const IntegrandSpec& spec, const TermSums& multipliers,
                               const QuadratureOptions& options) {
  require_tolerance(options);
  if (options.method == QuadratureMethod::adaptive) {
    std::size_t evaluations = 0;
    return integrate_adaptive(spec, multipliers, options, evaluations);
  }
  const TermIntegrals all = integrate_terms_gauss(spec, options);
  Estimate sum;
  for (std::size_t t = 0; t < k_term_count; ++t) {
    sum.value += multipliers[t] * all.terms[t].value;
    sum.error += std::abs(multipliers[t]) * all.terms[t].error;
  }
  return sum;
}

}  // namespace molchaos::theory::detail
