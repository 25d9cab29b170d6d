// Gauss–Hermite and generalised Gauss–Laguerre rules from GSL's fixed-point quadrature tables.
#include "molchaos/theory/gauss_rules.hpp"

#include <gsl/gsl_integration.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace molchaos::theory {
namespace {

GaussRule make_rule(const gsl_integration_fixed_type* type, int order, double a, double b,
                    double alpha) {
  if (order < 1 || order > 200)
    throw std::invalid_argument("order: value " + std::to_string(order) +
                                " is outside the allowed range [1, 200]");
  using Table =
      std::unique_ptr<gsl_integration_fixed_workspace, decltype(&gsl_integration_fixed_free)>;
  Table table(gsl_integration_fixed_alloc(type, static_cast<std::size_t>(order), a, b, alpha, 0.0),
              &gsl_integration_fixed_free);
  if (!table) throw std::runtime_error("Gauss rule: allocation failed");
  const double* x = gsl_integration_fixed_nodes(table.get());
  const double* w = gsl_integration_fixed_weights(table.get());
  return {std::vector<double>(x, x + order), std::vector<double>(w, w + order)};
}

}  // namespace

GaussRule gauss_hermite_rule(int order, double scale) {
  if (!(scale > 0.0)) throw std::invalid_argument("scale: must be positive");
  return make_rule(gsl_integration_fixed_hermite, order, 0.0, scale, 0.0);
}

GaussRule gauss_laguerre_rule(int order, double alpha) {
  if (!(alpha > -1.0)) throw std::invalid_argument("alpha: must exceed -1");
  return make_rule(gsl_integration_fixed_laguerre, order, 0.0, 1.0, alpha);
}

}  // namespace molchaos::theory
