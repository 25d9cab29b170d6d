// Contact statistics of a run over its homogeneous-cooling window.
#include "molchaos/validation/contact_measurement.hpp"

#include <cmath>

#include "molchaos/theory/cooling.hpp"
#include "molchaos/validation/haff_estimators.hpp"
#include "molchaos/validation/pair_correlations.hpp"

namespace molchaos::validation {

RunContacts measure_contacts(const sim::RunResult& run, const WindowRule& rule) {
  RunContacts r;
  const auto& p = run.parameters;
  r.seed = p.seed;
  r.impact_histogram.assign(sim::ContactMoments::k_impact_bins, 0);
  if (!p.contact_statistics) return r;
  const RunAnalysis a = analyse_run(run, rule);
  if (!a.ok) return r;
  r.A = a.A;
  r.a2 = a.a2;
  const double omega_unit = theory::enskog_collision_frequency(p.dimension, p.density, 1.0);
  double sum_P = 0, sum_Q = 0, sum_gn2 = 0, enskog_collisions = 0;
  std::uint64_t collisions = 0, counted = 0;
  for (std::size_t k = 1; k < run.samples.size(); ++k) {
    const auto& s = run.samples[k];
    const auto& prev = run.samples[k - 1];
    if (s.t <= a.window.t_start || s.t > a.window.t_stop) continue;
    collisions += s.collisions - prev.collisions;
    // Enskog's collisions per particle, ∫ω_E(T) dt with ω_E ∝ √T by the A estimator's rule (the
    // identity A ∝ 1/(W·Y) then holds run by run); pairs are N/2 times.
    enskog_collisions +=
        omega_unit * root_temperature_integral(prev.t, prev.temperature, s.t, s.temperature);
    const auto& c = s.contacts;
    counted += c.count;
    sum_P += c.sum_c1e_c2e;
    sum_Q += c.sum_c1_dot_c2;
    sum_gn2 += c.sum_gn2;
    for (int b = 0; b < sim::ContactMoments::k_impact_bins; ++b)
      r.impact_histogram[static_cast<std::size_t>(b)] +=
          c.impact_histogram[static_cast<std::size_t>(b)];
  }
  if (counted == 0 || enskog_collisions <= 0.0) return r;
  const double n = static_cast<double>(counted);
  r.collisions = collisions;
  r.measured.P = sum_P / n;
  r.measured.Q = sum_Q / n;
  r.measured.Y = 0.5 * sum_gn2 / n;  // (v12·e)²/(4T) = (c12·e)²/2
  r.measured.W = static_cast<double>(collisions) /
                 (0.5 * static_cast<double>(p.particles) * enskog_collisions);
  r.ok = true;
  return r;
}

FlatnessTest impact_flatness(const std::vector<std::uint64_t>& histogram) {
  FlatnessTest f;
  for (auto c : histogram) f.count += c;
  if (f.count == 0 || histogram.size() < 2) return f;
  const double expected = static_cast<double>(f.count) / static_cast<double>(histogram.size());
  for (auto c : histogram) {
    const double d = static_cast<double>(c) - expected;
    f.chi2 += d * d / expected;
  }
  f.dof = static_cast<int>(histogram.size()) - 1;
  f.p_value = chi_square_p_value(f.chi2, f.dof);
  return f;
}

}  // namespace molchaos::validation
