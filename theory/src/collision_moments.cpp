// Quadrature of the collision moments μ_p (see the header for the integral and its reduction).
#include "molchaos/theory/collision_moments.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "molchaos/theory/dimension.hpp"
#include "molchaos/theory/sonine.hpp"

namespace molchaos::theory {
namespace {

// Which polynomial in (S2(c1²), S2(c2²), D) multiplies the Maxwellian part of the integrand.
enum class Weight { full, one, a2, a2_squared, b, a2_b, a2_squared_b };

// What multiplies the weighted distribution: Δ(c1^p + c2^p) for the moments μ_p, or (for the
// contact averages) 1, the dyad D, or D².
enum class Observable { moment_change, one, dyad, dyad_squared };

struct IntegrandSpec {
  int dimension = 2;
  int moment = 2;
  Observable observable = Observable::moment_change;
  double restitution = 1.0;
  double dyad_factor = k_paper_dyad_factor;
  double a2 = 0.0;  // used by Weight::full only
  double b = 0.0;   // used by Weight::full only
  Weight weight = Weight::full;
};

// Tensor-product Gauss–Hermite rule for ∫ d^dC e^{−2C²} P(C), exact for polynomial P of degree
// ≤ 2·order − 1 in each component.
struct HermiteRule {
  std::vector<std::array<double, 3>> nodes;
  std::vector<double> weights;

  HermiteRule(int dimension, int order) {
    using Table =
        std::unique_ptr<gsl_integration_fixed_workspace, decltype(&gsl_integration_fixed_free)>;
    Table table(gsl_integration_fixed_alloc(gsl_integration_fixed_hermite,
                                            static_cast<std::size_t>(order), 0.0, 2.0, 0.0, 0.0),
                &gsl_integration_fixed_free);
    if (!table) throw std::runtime_error("Gauss-Hermite rule: allocation failed");
    const double* x = gsl_integration_fixed_nodes(table.get());
    const double* w = gsl_integration_fixed_weights(table.get());
    const int n = order;
    const int total = dimension == 2 ? n * n : n * n * n;
    for (int k = 0; k < total; ++k) {
      std::array<double, 3> node{0.0, 0.0, 0.0};
      double weight = 1.0;
      int rest = k;
      for (int axis = 0; axis < dimension; ++axis) {
        node[axis] = x[rest % n];
        weight *= w[rest % n];
        rest /= n;
      }
      // d = 3: g lies in the x–y plane, so the integrand is even in C_z; fold C_z < 0 onto C_z > 0.
      if (dimension == 3) {
        if (node[2] < -1e-12) continue;
        if (node[2] > 1e-12) weight *= 2.0;
      }
      nodes.push_back(node);
      weights.push_back(weight);
    }
  }
};

double power_p(double square, int p) { return p == 2 ? square : square * square; }

class MomentIntegrand {
 public:
  MomentIntegrand(const IntegrandSpec& spec, const QuadratureOptions& options)
      : spec_(spec),
        rule_(spec.dimension, options.hermite_order > 0 ? options.hermite_order
                                                        : exact_hermite_order(spec.moment)) {}

  // Sum over the centre-of-mass velocity C at fixed relative velocity g = (−u, ρ, 0).
  double at(double u, double rho) {
    ++evaluations_;
    const int d = spec_.dimension;
    const std::array<double, 3> g{-u, rho, 0.0};
    const double gn = g[0];                                    // g·e with e = x̂
    const double kick = 0.5 * (1.0 + spec_.restitution) * gn;  // collision rule, eq. coll
    double sum = 0.0;
    for (std::size_t k = 0; k < rule_.nodes.size(); ++k) {
      const auto& C = rule_.nodes[k];
      std::array<double, 3> c1{}, c2{};
      for (int i = 0; i < d; ++i) {
        c1[i] = C[i] + 0.5 * g[i];
        c2[i] = C[i] - 0.5 * g[i];
      }
      double c1sq = 0.0, c2sq = 0.0, c1c2 = 0.0;
      for (int i = 0; i < d; ++i) {
        c1sq += c1[i] * c1[i];
        c2sq += c2[i] * c2[i];
        c1c2 += c1[i] * c2[i];
      }
      // Post-collision velocities: only the x (normal) components change.
      const double c1x_after = c1[0] - kick;
      const double c2x_after = c2[0] + kick;
      const double c1sq_after = c1sq - c1[0] * c1[0] + c1x_after * c1x_after;
      const double c2sq_after = c2sq - c2[0] * c2[0] + c2x_after * c2x_after;
      const int p = spec_.moment;
      const double delta =
          power_p(c1sq_after, p) + power_p(c2sq_after, p) - power_p(c1sq, p) - power_p(c2sq, p);
      const double s1 = sonine_s2(d, c1sq);
      const double s2 = sonine_s2(d, c2sq);
      const double dyad = spec_.dyad_factor * c1[0] * c2[0] - c1c2;  // D̂:c1c2, eq. c1Dc2
      double observable = delta;
      switch (spec_.observable) {
        case Observable::moment_change:
          break;
        case Observable::one:
          observable = 1.0;
          break;
        case Observable::dyad:
          observable = dyad;
          break;
        case Observable::dyad_squared:
          observable = dyad * dyad;
          break;
      }
      sum += rule_.weights[k] * weight(s1, s2, dyad) * observable;
    }
    const double maxwell_g = std::exp(-0.5 * (u * u + rho * rho));  // e^{−g²/2}
    const double tangential_measure = d == 2 ? 2.0 : 2.0 * std::numbers::pi * rho;
    return u * maxwell_g * tangential_measure * sum;
  }

  [[nodiscard]] std::size_t evaluations() const { return evaluations_; }

 private:
  [[nodiscard]] double weight(double s1, double s2, double dyad) const {
    switch (spec_.weight) {
      case Weight::full:
        return (1.0 + spec_.a2 * s1) * (1.0 + spec_.a2 * s2) * (1.0 + spec_.b * dyad);
      case Weight::one:
        return 1.0;
      case Weight::a2:
        return s1 + s2;
      case Weight::a2_squared:
        return s1 * s2;
      case Weight::b:
        return dyad;
      case Weight::a2_b:
        return (s1 + s2) * dyad;
      case Weight::a2_squared_b:
        return s1 * s2 * dyad;
    }
    return 0.0;
  }

  IntegrandSpec spec_;
  HermiteRule rule_;
  std::size_t evaluations_ = 0;
};

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

struct NestedResult {
  Estimate estimate;
  std::size_t evaluations = 0;
};

// Absolute accuracy floor, relative to the O(1) size of the moments: without it an integral that
// vanishes (μ2 at ε = 1, an inner integral at a sign change) could never meet a relative
// tolerance. The reported error estimate stays honest either way.
constexpr double k_absolute_floor = 1e-3;

// The outer integrand is itself an adaptive integral over the tangential speed; its error
// estimate err(u) is kept so that ∫ err(u) du can be added to the outer error estimate.
struct NestedState {
  MomentIntegrand* integrand;
  gsl_integration_workspace* inner_ws;
  std::size_t limit;
  double inner_tol;
  double u;
  double last_error;
};

double inner_integral(double u, NestedState* s) {
  s->u = u;
  gsl_function f;
  f.params = s;
  f.function = [](double rho, void* q) {
    auto* t = static_cast<NestedState*>(q);
    return t->integrand->at(t->u, rho);
  };
  double value = 0.0, error = 0.0;
  check_status(gsl_integration_qagiu(&f, 0.0, k_absolute_floor * s->inner_tol, s->inner_tol,
                                     s->limit, s->inner_ws, &value, &error),
               "inner (tangential) quadrature");
  s->last_error = error;
  return value;
}

// μ_p = −½ |S^{d−1}| π^{−d} ∫_0^∞ du ∫_0^∞ dρ m(ρ) Σ_C w_C (...)
NestedResult integrate(const IntegrandSpec& spec, const QuadratureOptions& options) {
  if (!(options.relative_tolerance > 0.0 && options.relative_tolerance < 1.0))
    throw std::invalid_argument("relative_tolerance: must lie in (0, 1)");
  gsl_set_error_handler_off();
  MomentIntegrand integrand(spec, options);
  const double outer_tol = options.relative_tolerance;
  const double inner_tol = std::max(0.1 * outer_tol, 1e-14);
  Workspace outer_ws = make_workspace(options.workspace_intervals);
  Workspace inner_ws = make_workspace(options.workspace_intervals);

  NestedState state{&integrand, inner_ws.get(), options.workspace_intervals, inner_tol, 0.0, 0.0};
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
  // μ_p carries −½ (eq. defmu2); the contact integrals are plain averages over colliding pairs.
  const double sign_half = spec.observable == Observable::moment_change ? -0.5 : 1.0;
  const double prefactor =
      sign_half * unit_sphere_area(spec.dimension) / std::pow(std::numbers::pi, spec.dimension);
  const double total_error = error + inner_error + inner_error_error;
  return {{prefactor * value, std::abs(prefactor) * total_error}, integrand.evaluations()};
}

void require_moment(int p) {
  if (p != 2 && p != 4)
    throw std::invalid_argument("moment: value " + std::to_string(p) +
                                " is not allowed; allowed values 2 or 4");
}

}  // namespace

int exact_hermite_order(int p) {
  // Degree in each C component: S2·S2·D contributes ≤ 4 + 4 + 2, Δ(c^p) ≤ p. A rule of order n
  // integrates degree 2n − 1 exactly.
  const int degree = 10 + p;
  return degree / 2 + 1;
}

Estimate collision_moment(int dimension, int p, double restitution, double a2, double b,
                          double dyad_factor, const QuadratureOptions& options) {
  require_dimension(dimension);
  require_moment(p);
  require_restitution(restitution);
  IntegrandSpec spec{dimension,   p, Observable::moment_change, restitution, dyad_factor, a2, b,
                     Weight::full};
  return integrate(spec, options).estimate;
}

const ExpansionTerm& ExpansionTable::term(const std::string& name) const {
  for (const auto& t : terms)
    if (t.name == name) return t;
  throw std::out_of_range("no expansion term named '" + name + "'");
}

double ExpansionTable::ratio(double a2, double b) const {
  double r = 1.0;
  for (const auto& t : terms)
    r += t.coefficient.value * std::pow(a2, t.a2_power) * std::pow(b, t.b_power);
  return r;
}

ExpansionTable expand_collision_moment(int dimension, int p, double restitution, double dyad_factor,
                                       const QuadratureOptions& options) {
  require_dimension(dimension);
  require_moment(p);
  require_restitution(restitution);
  if (restitution == 1.0 && p == 2)
    throw std::invalid_argument(
        "restitution: μ2 vanishes at ε = 1, so its coefficients are undefined; allowed range (0, "
        "1)");
  ExpansionTable table;
  table.dimension = dimension;
  table.moment = p;
  table.restitution = restitution;
  table.dyad_factor = dyad_factor;
  table.relative_tolerance = options.relative_tolerance;
  IntegrandSpec spec{dimension,  p, Observable::moment_change, restitution, dyad_factor, 0.0, 0.0,
                     Weight::one};
  NestedResult base = integrate(spec, options);
  table.base = base.estimate;
  table.integrand_evaluations = base.evaluations;
  struct Row {
    const char* name;
    int a2_power, b_power;
    Weight weight;
  };
  const Row rows[] = {{"a2", 1, 0, Weight::a2},
                      {"a2^2", 2, 0, Weight::a2_squared},
                      {"b", 0, 1, Weight::b},
                      {"a2*b", 1, 1, Weight::a2_b},
                      {"a2^2*b", 2, 1, Weight::a2_squared_b}};
  for (const Row& row : rows) {
    spec.weight = row.weight;
    NestedResult r = integrate(spec, options);
    table.integrand_evaluations += r.evaluations;
    table.terms.push_back(
        {row.name, row.a2_power, row.b_power, r.estimate, divide(r.estimate, table.base)});
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
  IntegrandSpec spec{dimension, 2, Observable::one, 1.0, dyad_factor, a2, 0.0, Weight::full};
  out.one = integrate(spec, options).estimate;
  spec.observable = Observable::dyad;
  out.dyad = integrate(spec, options).estimate;
  spec.observable = Observable::dyad_squared;
  out.dyad_squared = integrate(spec, options).estimate;
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
