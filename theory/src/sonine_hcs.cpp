// a2, a3 of the homogeneous cooling state from the moment equations (see the header).
#include "molchaos/theory/sonine_hcs.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "molchaos/theory/dimension.hpp"

namespace molchaos::theory {
namespace {

// μ_p(a2, a3) at b = 0 from its term integrals, with the gradient and the propagated error.
struct MomentPolynomial {
  ExpansionTable table;

  struct Value {
    double value = 0.0, d_a2 = 0.0, d_a3 = 0.0, error = 0.0;
  };

  [[nodiscard]] Value at(double a2, double a3) const {
    Value v{table.base.value, 0.0, 0.0, table.base.error};
    for (const ExpansionTerm& t : table.terms) {
      if (t.b_power != 0) continue;
      const int i = t.a2_power, j = t.a3_power;
      const double I = t.integral.value;
      v.value += I * std::pow(a2, i) * std::pow(a3, j);
      if (i > 0) v.d_a2 += I * i * std::pow(a2, i - 1) * std::pow(a3, j);
      if (j > 0) v.d_a3 += I * j * std::pow(a2, i) * std::pow(a3, j - 1);
      v.error += t.integral.error * std::abs(std::pow(a2, i) * std::pow(a3, j));
    }
    return v;
  }
};

struct Equations {
  int dimension;
  MomentPolynomial mu2, mu4, mu6;
};

// F = (F4, F6), its Jacobian and the error of F from the quadrature errors of the moments.
struct Residual {
  std::array<double, 2> f{}, error{};
  std::array<std::array<double, 2>, 2> jacobian{};
};

Residual residual(const Equations& eq, double a2, double a3) {
  const double d = eq.dimension;
  const double k4 = d + 2.0, k6 = 0.75 * (d + 2.0) * (d + 4.0);
  const auto m2 = eq.mu2.at(a2, a3), m4 = eq.mu4.at(a2, a3), m6 = eq.mu6.at(a2, a3);
  const double w4 = k4 * (1.0 + a2), w6 = k6 * (1.0 + 3.0 * a2 - a3);
  Residual r;
  r.f = {m4.value - w4 * m2.value, m6.value - w6 * m2.value};
  r.error = {m4.error + std::abs(w4) * m2.error, m6.error + std::abs(w6) * m2.error};
  r.jacobian[0] = {m4.d_a2 - k4 * m2.value - w4 * m2.d_a2, m4.d_a3 - w4 * m2.d_a3};
  r.jacobian[1] = {m6.d_a2 - 3.0 * k6 * m2.value - w6 * m2.d_a2,
                   m6.d_a3 + k6 * m2.value - w6 * m2.d_a3};
  return r;
}

// Solves J δ = −F in one (a3 fixed at 0) or two unknowns; `errors` gets |J⁻¹|·error(F).
std::array<double, 2> newton_step(const Residual& r, bool with_a3, std::array<double, 2>& errors) {
  if (!with_a3) {
    const double j = r.jacobian[0][0];
    errors = {r.error[0] / std::abs(j), 0.0};
    return {-r.f[0] / j, 0.0};
  }
  const auto& J = r.jacobian;
  const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  const std::array<std::array<double, 2>, 2> inv{
      {{J[1][1] / det, -J[0][1] / det}, {-J[1][0] / det, J[0][0] / det}}};
  errors = {std::abs(inv[0][0]) * r.error[0] + std::abs(inv[0][1]) * r.error[1],
            std::abs(inv[1][0]) * r.error[0] + std::abs(inv[1][1]) * r.error[1]};
  return {-(inv[0][0] * r.f[0] + inv[0][1] * r.f[1]), -(inv[1][0] * r.f[0] + inv[1][1] * r.f[1])};
}

// The cooling-rate factor at the solution, with the errors of the moments and of (a2, a3).
SonineSolution finish(const std::string& level, const Equations& eq, double a2, double a3,
                      const std::array<double, 2>& errors) {
  const auto m = eq.mu2.at(a2, a3);
  const Estimate& base = eq.mu2.table.base;
  const double ratio = m.value / base.value;
  const double ratio_error =
      (m.error + std::abs(ratio) * base.error) / std::abs(base.value) +
      (std::abs(m.d_a2) * errors[0] + std::abs(m.d_a3) * errors[1]) / std::abs(base.value);
  return {level,
          {a2, errors[0]},
          {a3, errors[1]},
          {ratio, ratio_error},
          {1.0 / ratio, ratio_error / (ratio * ratio)}};
}

// The linearised equations: one step from (0, 0). The full ones: Newton from the linear root.
SonineSolution solve(const std::string& level, const Equations& eq, bool with_a3, bool linear,
                     std::array<double, 2> start) {
  std::array<double, 2> errors{};
  if (linear) {
    const auto x = newton_step(residual(eq, 0.0, 0.0), with_a3, errors);
    // The error of F at the solution of the linearised equations, propagated the same way.
    const Residual at_x = residual(eq, x[0], x[1]);
    Residual linearised = residual(eq, 0.0, 0.0);
    linearised.error = at_x.error;
    newton_step(linearised, with_a3, errors);
    return finish(level, eq, x[0], x[1], errors);
  }
  std::array<double, 2> x = start;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const auto step = newton_step(residual(eq, x[0], x[1]), with_a3, errors);
    x = {x[0] + step[0], x[1] + step[1]};
    if (std::abs(step[0]) + std::abs(step[1]) <= 1e-15 * (1.0 + std::abs(x[0]) + std::abs(x[1])))
      break;
  }
  newton_step(residual(eq, x[0], x[1]), with_a3, errors);
  return finish(level, eq, x[0], x[1], errors);
}

}  // namespace

HcsSonine hcs_sonine_coefficients(int dimension, double restitution,
                                  const QuadratureOptions& options) {
  require_dimension(dimension);
  require_restitution(restitution);
  if (restitution == 1.0) {  // elastic: the Maxwellian is exact, nothing dissipates
    const SonineSolution maxwell{"", {0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}};
    HcsSonine out{maxwell, maxwell, maxwell, maxwell};
    out.first_sonine.level = "first_sonine";
    out.a2_nonlinear.level = "a2_nonlinear";
    out.a2_a3_linear.level = "a2_a3_linear";
    out.a2_a3.level = "a2_a3";
    return out;
  }
  auto table = [&](int p) {
    return MomentPolynomial{expand_collision_moment(dimension, p, restitution, k_paper_dyad_factor,
                                                    options, SonineTerms::a2_a3)};
  };
  const Equations eq{dimension, table(2), table(4), table(6)};
  HcsSonine out;
  out.first_sonine = solve("first_sonine", eq, false, true, {});
  out.a2_nonlinear = solve("a2_nonlinear", eq, false, false, {out.first_sonine.a2.value, 0.0});
  out.a2_a3_linear = solve("a2_a3_linear", eq, true, true, {});
  out.a2_a3 =
      solve("a2_a3", eq, true, false, {out.a2_a3_linear.a2.value, out.a2_a3_linear.a3.value});
  return out;
}

}  // namespace molchaos::theory
