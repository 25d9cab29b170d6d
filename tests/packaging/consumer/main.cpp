// Uses the installed molchaos::theory and molchaos::sim: exact values of the theory and a short
// elastic simulation that must conserve the temperature. Exit status 0 when both hold.
#include <cmath>
#include <cstdio>

#include "molchaos/sim/run.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/sonine.hpp"

int main() {
  namespace theory = molchaos::theory;
  namespace sim = molchaos::sim;
  // Elastic limit: the first-Sonine a2 vanishes, and Haff's law gives T0/4 at t = τ0.
  const double a2 = theory::a2_first_sonine(2, 1.0);
  const double T_at_tau0 = theory::haff_temperature(10.0, 1.0, 10.0);
  sim::Parameters p;
  p.particles = 100;
  p.density = 0.05;
  p.restitution = 1.0;
  p.t_end = 5.0;
  p.relax_collisions_per_particle = 2.0;
  const sim::RunResult r = sim::run(p);
  const double T_end = r.samples.back().temperature;
  // An elastic run conserves energy to rounding (the engine's tests: drift < 1e-12).
  const bool ok = a2 == 0.0 && std::abs(T_at_tau0 - 0.25) < 1e-15 && std::abs(T_end - 1.0) < 1e-12;
  std::printf("a2(eps = 1) = %g, T(tau0)/T0 = %.17g, elastic T(t_end)/T0 = %.17g: %s\n", a2,
              T_at_tau0, T_end, ok ? "ok" : "FAILED");
  return ok ? 0 : 1;
}
