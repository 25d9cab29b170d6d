// Collisions per particle of a cooling run, estimated from the homogeneous gas's temperature T(t).
#include "molchaos/sim/run_length.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace molchaos::sim {

double estimated_collisions_per_particle(const RunLengthGas& gas, double t) {
  const double w = gas.collision_frequency;
  const double cooling = (1.0 - gas.restitution) * (1.0 + gas.restitution);
  if (!(cooling > 0)) return w * t;
  // Haff's law with the first-order cooling rate ζ = (1 − ε²) ω_E √T / d: T = (1 + t/τ0)^−2 with
  // τ0 = 2d/((1 − ε²) ω_E), and ω_E τ0 ln(1 + t/τ0) collisions per particle, until T reaches the
  // stop temperature at t_stop.
  const double tau0 = 2.0 * gas.dimension / (cooling * w);
  const double x_stop = std::sqrt(gas.stop_temperature);  // x = √T
  if (gas.tc <= 0) {
    const double t_stop = tau0 * (1.0 / x_stop - 1.0);
    return w * tau0 * std::log1p(std::min(t, t_stop) / tau0);
  }
  // TC model: a collision is elastic when either partner collided less than tc ago. A particle's
  // time since its last collision is about exponential with rate ω_E x, so a fraction e^{−a x},
  // a = 2 ω_E tc, of the collisions dissipate, and dx/dt = −(x²/τ0) e^{−a x}, dc/dt = ω_E x.
  // Integrated by RK4 in ln t from t0 = 1e-6 τ0 (x = 1 there to 1e-6), 40 steps per e-fold on a
  // grid that does not depend on t (the last step cut at t). Measured (ε = 0.5, n = 0.05,
  // N = 2000, t = 3000): tc = 2 gives 29.6 against 33.3 collisions per particle of the run,
  // tc = 20 gives 548 against 492 (the run's first collisions all dissipate). Where clusters form
  // (strong dissipation) their collisions come on top: ε = 0.5, tc = 20 to t = 1e13 estimated
  // 1.7e3 against 1.4e5 per particle (5.6e8 events, which the check allows).
  const double a = 2.0 * w * gas.tc;
  const double t0 = 1e-6 * tau0;
  if (!(t > t0)) return w * t;
  const double log_end = std::log(t);
  constexpr double h_max = 1.0 / 40.0;
  struct Rate {
    double x, c;  // d/d(ln t) of x and of the collisions
  };
  const auto rate = [&](double log_t, double x) {
    const double time = std::exp(log_t);
    return Rate{-time * x * x / tau0 * std::exp(-a * x), w * x * time};
  };
  double x = 1.0, c = w * t0, log_t = std::log(t0);
  while (log_t < log_end && x > x_stop) {
    const double h = std::min(h_max, log_end - log_t);
    const Rate k1 = rate(log_t, x);
    const Rate k2 = rate(log_t + h / 2, x + h / 2 * k1.x);
    const Rate k3 = rate(log_t + h / 2, x + h / 2 * k2.x);
    const Rate k4 = rate(log_t + h, x + h * k3.x);
    x += h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x);
    c += h / 6 * (k1.c + 2 * k2.c + 2 * k3.c + k4.c);
    log_t += h;
  }
  return c;
}

std::string estimated_count(double expected, const std::string& unit) {
  if (!std::isfinite(expected)) return "more " + unit + " than a double holds";
  char digits[32];
  std::snprintf(digits, sizeof digits, "%.2g", expected);
  return "about " + std::string(digits) + " " + unit;
}

double longest_time_within(const std::function<double(double)>& cost, double t_end, double budget) {
  if (!(cost(t_end) > budget)) return t_end;
  double lo = 0.0, hi = t_end;
  for (int k = 0; k < 200 && hi > lo * (1.0 + 1e-12); ++k) {
    const double mid = lo > 0 ? std::sqrt(lo) * std::sqrt(hi) : hi * 1e-300;  // lo·hi may overflow
    (cost(mid) > budget ? hi : lo) = mid;
  }
  // Three digits, rounded down (an estimate; the value shown must itself be allowed).
  if (!(lo > 0)) return lo;
  const double unit = std::pow(10.0, std::floor(std::log10(lo)) - 2.0);
  return std::max(std::floor(lo / unit) * unit, std::nextafter(0.0, 1.0));
}

}  // namespace molchaos::sim
