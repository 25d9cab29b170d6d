// From the contact measurements of the original and the molecular-chaos (flux-shuffled) gas to
// the study's tables: ensemble contact moments, the cooling rate taken apart into collision
// frequency and energy loss per collision, the ansatz fitted at contact, the two routes to b.
#pragma once

#include <string>
#include <vector>

#include "molchaos/validation/contact_measurement.hpp"
#include "molchaos/validation/correlation_tables.hpp"

namespace molchaos::validation {

/// The runs of one state point in both gases (runs with the same seed start from the same state).
struct GasPair {
  int dimension = 2;
  double density = 0.0, restitution = 0.0;
  std::vector<RunContacts> original, chaos;
};

/// Ensemble means ± standard errors of one gas's runs (failed runs left out).
ContactMomentRow summarize_contacts(int dimension, double density, double restitution,
                                    const std::string& mode, const std::vector<RunContacts>& runs);

CoolingDecompositionRow decompose_cooling(const GasPair& point);

/// The ansatz's fits at every point. The four shifts of a point are correlated (same runs); their
/// covariance is the per-point standard errors times the correlation matrix pooled over the
/// points of the same dimension and density (a 4×4 matrix from ~8 seeds alone would bias χ²).
std::vector<AnsatzFitRow> fit_ansatz(const std::vector<GasPair>& points);

/// An amplitude from the cooling rate against the same from the contact statistics over all
/// points: ratio (weighted fit through the origin, errors in both and their covariance) and χ² of
/// equality from the paired per-point differences (t scores mapped to normal scores).
/// `amplitude` names it in the statement, e.g. "b".
BRoutesVerdict compare_routes(const std::vector<RoutePair>& routes, const std::string& amplitude);

/// The dyad factor of the printed ansatz, 3r̂r̂ − U.
inline constexpr double k_printed_dyad_factor = 3.0;

}  // namespace molchaos::validation
