// The centre-of-mass sum of the collision integrand (see collision_integrand.hpp).
#include "collision_integrand.hpp"

#include <cmath>

#include "molchaos/theory/sonine.hpp"

namespace molchaos::theory::detail {

int polynomial_degree(const IntegrandSpec& spec) {
  // S2(c1²)S2(c2²) has degree 8, S3(c1²)S3(c2²) 12; the dyad D adds 2.
  const int weight = (spec.with_a3 ? 12 : 8) + 2;
  switch (spec.observable) {
    case Observable::moment_change:
      return weight + spec.moment;
    case Observable::one:
      return weight;
    default:
      return weight + 2;
  }
}

CentreOfMassSum::CentreOfMassSum(const IntegrandSpec& spec, int hermite_order) : spec_(spec) {
  const GaussRule rule = gauss_hermite_rule(hermite_order, 2.0);
  const int n = hermite_order;
  const int d = spec.dimension;
  const int total = d == 2 ? n * n : n * n * n;
  for (int k = 0; k < total; ++k) {
    std::array<double, 3> node{0.0, 0.0, 0.0};
    double weight = 1.0;
    int rest = k;
    for (int axis = 0; axis < d; ++axis) {
      node[axis] = rule.nodes[rest % n];
      weight *= rule.weights[rest % n];
      rest /= n;
    }
    // d = 3: g lies in the x–y plane, so the integrand is even in C_z; fold C_z < 0 onto C_z > 0.
    if (d == 3) {
      if (node[2] < -1e-12) continue;
      if (node[2] > 1e-12) weight *= 2.0;
    }
    nodes_.push_back(node);
    weights_.push_back(weight);
  }
}

namespace {

// (x + δ)^{p/2} − x^{p/2} with the factor δ taken out: p = 2, 4, 6.
double change_of_power(double x, double delta, int p) {
  const double y = x + delta;
  switch (p) {
    case 2:
      return delta;
    case 4:
      return delta * (y + x);
    default:
      return delta * (y * y + y * x + x * x);
  }
}

}  // namespace

void CentreOfMassSum::accumulate(double u, double rho, double scale, TermSums& sums,
                                 TermSums& magnitudes) const {
  const int d = spec_.dimension;
  const double g[3] = {-u, rho, 0.0};
  // The collision rule, the paper's Eqs. (5), (6).
  const double kick = 0.5 * (1.0 + spec_.restitution) * g[0];
  const int p = spec_.moment;
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const auto& C = nodes_[k];
    double c1sq = 0.0, c2sq = 0.0, c1c2 = 0.0;
    for (int i = 0; i < d; ++i) {
      const double a = C[i] + 0.5 * g[i], b = C[i] - 0.5 * g[i];
      c1sq += a * a;
      c2sq += b * b;
      c1c2 += a * b;
    }
    const double c1n = C[0] + 0.5 * g[0], c2n = C[0] - 0.5 * g[0];  // normal components
    const double normal_product = c1n * c2n;
    const double dyad = spec_.dyad_factor * normal_product - c1c2;  // D̂:c1c2, paper Eq. (16)
    double observable = 1.0;
    switch (spec_.observable) {
      case Observable::moment_change: {
        // Only the normal components change in a collision. The changes of c² are formed
        // directly (δ = c²_after − c²), not as a difference of large squares, so that rounding
        // stays relative to the integrand and not to the speeds at the outer nodes.
        const double delta1 = kick * (kick - 2.0 * c1n), delta2 = kick * (kick + 2.0 * c2n);
        observable = change_of_power(c1sq, delta1, p) + change_of_power(c2sq, delta2, p);
        break;
      }
      case Observable::one:
        break;
      case Observable::normal_product:
        observable = normal_product;
        break;
      case Observable::velocity_product:
        observable = c1c2;
        break;
      case Observable::dyad:
        observable = dyad;
        break;
      case Observable::normal_speed_squared:
        observable = u * u;
        break;
    }
    const double s1 = sonine_s2(d, c1sq), s2 = sonine_s2(d, c2sq);
    TermSums w{};
    w[0] = 1.0;
    w[1] = s1 + s2;
    w[2] = s1 * s2;
    if (spec_.with_a3) {
      const double t1 = sonine_s3(d, c1sq), t2 = sonine_s3(d, c2sq);
      w[6] = t1 + t2;
      w[7] = s1 * t2 + t1 * s2;
      w[8] = t1 * t2;
    }
    for (std::size_t t = 0; t < 3; ++t) w[t + 3] = w[t] * dyad;
    for (std::size_t t = 6; t < 9; ++t) w[t + 3] = w[t] * dyad;
    const double common = scale * weights_[k] * observable;
    const std::size_t used = spec_.with_a3 ? k_term_count : k_a2_term_count;
    for (std::size_t t = 0; t < used; ++t) {
      const double v = common * w[t];
      sums[t] += v;
      magnitudes[t] += std::abs(v);
    }
  }
}

}  // namespace molchaos::theory::detail
