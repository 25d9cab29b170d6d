// What the collisions of one run show in its homogeneous-cooling window (the Haff fit's window):
// the collision frequency over Enskog's at the same T, the energy loss per collision, the two
// velocity moments at contact, the impact-parameter histogram; and their ensemble estimates.
#pragma once

#include <cstdint>
#include <vector>

#include "molchaos/sim/result.hpp"
#include "molchaos/validation/analysis.hpp"
#include "molchaos/validation/contact_ansatz.hpp"

namespace molchaos::validation {

struct RunContacts {
  bool ok = false;
  std::uint64_t seed = 0;
  double A = 0.0;              ///< Haff fit, τ0(T0 = 1)(1 − ε²)
  double a2 = 0.0;             ///< mean over the window
  ContactQuantities measured;  ///< P, Q, W = ω/ω_Enskog(T(t)), Y = ⟨(v12·e)²⟩/(4T)
  std::uint64_t collisions = 0;
  std::vector<std::uint64_t> impact_histogram;  ///< all zeros if the engine did not fill it
};

/// Sums the contact statistics of the samples inside the window (sample s covers (s_prev, s]);
/// W integrates Enskog's frequency over the same intervals by the integrated Haff estimator's rule
/// (root_temperature_integral), so that A ∝ 1/(W·Y) holds run by run.
/// ok = false if the run has no valid window or no contact statistics.
RunContacts measure_contacts(const sim::RunResult& run, const WindowRule& rule);

/// Impact-parameter histogram against flat: χ², dof = bins − 1 (multinomial counts).
struct FlatnessTest {
  double chi2 = 0.0;
  int dof = 0;
  double p_value = 1.0;
  std::uint64_t count = 0;
};
FlatnessTest impact_flatness(const std::vector<std::uint64_t>& histogram);

}  // namespace molchaos::validation
