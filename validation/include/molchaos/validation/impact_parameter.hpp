// The impact-parameter distribution of the colliding pairs, per gas and state point: the
// histogram's fractions with their errors over runs, its flatness (molecular chaos makes it
// uniform), and the study's claims on it (global χ² per gas, the direction of grazing collisions).
#pragma once

#include <string>
#include <vector>

#include "molchaos/validation/contact_measurement.hpp"
#include "molchaos/validation/correlation_tables.hpp"

namespace molchaos::validation {

/// One row per bin for one gas at one state point (runs without contact statistics left out);
/// empty if no run has any.
std::vector<ImpactParameterRow> summarize_impact_parameter(int dimension, double density,
                                                           double restitution,
                                                           const std::string& mode,
                                                           const std::vector<RunContacts>& runs);

/// Per gas: flat at every point (Pearson χ² summed over all points, dof summed), and the
/// departure of the grazing bin (s → 1) from flat, weighted over all points.
std::vector<StudyClaim> impact_parameter_claims(const std::vector<ImpactParameterRow>& rows);

/// The table as CSV text; `header` (lines starting with '#') goes first.
std::string impact_parameter_csv(const std::vector<ImpactParameterRow>& rows,
                                 const std::string& header);

}  // namespace molchaos::validation
