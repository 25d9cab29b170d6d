// Everything `molchaos theory` reports for one state point, computed once: the prediction (g2,
// a2, μ2, τ0, A), the paper's μ2 coefficients and prefactors against quadrature, the allowed b,
// the homogeneous cooling state at four levels of Sonine theory, the contact averages under the
// paper's ansatz, and the linear hydrodynamics of the box. The CLI prints it as text or JSON, the
// Python module returns the JSON (theory_report_json.hpp): one computation, one document.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/contact_response.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/correlation_range.hpp"
#include "molchaos/theory/estimate.hpp"
#include "molchaos/theory/hydrodynamics.hpp"
#include "molchaos/theory/paper_checks.hpp"
#include "molchaos/theory/sonine_hcs.hpp"

namespace molchaos::theory {

/// The box whose largest shear mode the report follows: N particles at the state's density.
struct BoxInputs {
  /// Particles N: the box side is L = (N/n)^{1/d}, the largest shear mode 2π/L.
  std::int64_t particles = 5000;
  /// The level of that mode's S⊥ (1 in equilibrium) whose time is reported.
  double growth = 10.0;
};
inline constexpr std::int64_t k_min_box_particles = 2;
inline constexpr std::int64_t k_max_box_particles = 100000000;
inline constexpr double k_max_growth = 1e12;  ///< growth in (1, k_max_growth]

struct ReportInputs {
  int dimension = 2;
  double restitution = 0.9;
  double density = 0.05;
  double correlation_b = 0.0;  ///< the paper's b, in correlation_b_range()
  QuadratureOptions quadrature{};
  BoxInputs box{};
};

/// Refuses (std::invalid_argument, the message starting "particles:" or "growth:" and naming
/// the allowed range) a box outside the ranges above. The state point itself is checked by
/// predict_cooling() when the report is computed.
void require_box(const BoxInputs& box);

/// The largest shear mode 2π/L of the box on Haff's law.
struct LargestShearMode {
  double box = 0, wavenumber = 0, rate = 0, collisions = 0, time = 0;
  double log_time = 0;  ///< ln t, finite where t overflows a double
  double stationary_level = 0;  ///< S⊥ at which a decaying mode settles; +inf where it grows
};
LargestShearMode largest_shear_mode(const TransportCoefficients& c, const ReportInputs& in);

struct TheoryReport {
  CoolingPrediction prediction;
  ExpansionTable table;      ///< μ2's coefficients with the paper's dyad 3·ee − U
  ExpansionTable traceless;  ///< the same with the traceless dyad d·ee − U
  std::vector<PaperCheck> coefficient_rows, prefactor_rows;
  CorrelationRange b_range;
  HcsSonine sonine;
  /// A with each level's a2, a3 and the given b; none where that μ2 is not positive beyond its
  /// error (the b range makes sure of it for the first level only): the gas would not cool.
  std::array<std::optional<Estimate>, 4> A_by_level;
  std::array<Estimate, 4> mu2_ratio_at_b;  ///< μ2/μ2(0,0) behind each A, at the given b
  ContactResponse contact, contact_traceless;
  TransportCoefficients transport;
  LargestShearMode shear_mode;
  double seconds = 0.0;  ///< the computation's wall time
};

/// The Sonine levels in the report's order: first Sonine, a2 nonlinear, a2 and a3 linear, both.
std::array<const SonineSolution*, 4> levels(const HcsSonine& h);

/// The exact form the symbolic derivation gives for a term of μ2's expansion with the dyad
/// factor κ ("-" where it gives none).
std::string exact_form(int dimension, double dyad_factor, const std::string& term);

/// The contact response's five quantities by the names the symbolic derivation gives them.
std::array<std::pair<const char*, const ResponseSeries*>, 5> contact_rows(const ContactResponse& c);

/// The whole report. Throws std::invalid_argument naming the field (density, restitution,
/// correlation_b, particles, growth) for a state point or box out of range.
TheoryReport compute_report(const ReportInputs& in);

}  // namespace molchaos::theory
