// Ensembles grown in stages until every state point's A has a target relative standard error:
// how many seeds each point gets comes from seed_sizing.hpp, the runs go through the sweep runner
// (threads or MPI) and the cache, from which the seeds of earlier stages are read back. Used by
// `reproduce` for Fig. 4 and by `sweep --target-error`.
#pragma once

#include <vector>

#include "molchaos/validation/ensemble.hpp"
#include "molchaos/validation/seed_sizing.hpp"
#include "molchaos/validation/sweep.hpp"

namespace molchaos::validation {

/// Further stages at most: each sizes from more runs than the one before. A point that grows at
/// most 4-fold per stage from a first stage of 3–8 seeds may reach its need (up to 192) only in
/// the third or fourth; one stage more sizes its neighbours from the model its growth moved.
inline constexpr int k_target_stages = 5;

/// One list of point results and the ensemble they were summarized from, whose
/// target_relative_error and max_seeds size its points (nothing is added when the target is 0). A
/// gas is one method and mode at one density; its points differ in restitution.
struct StagedList {
  std::vector<PointResult>* points;
  const EnsembleSpec* spec;
};

/// Runs up to k_target_stages further stages over all lists (one sweep per stage), replacing each
/// grown point's result by the summary of all its seeds; stops early when no point needs more
/// seeds. Then every point of a list with a target reports SE(A) from reported_relative_scatter
/// (its own scatter, or its gas's model where that is larger), since its own decided when it
/// stopped, times the factor of stopping_correction.hpp for what stopping still leaves short.
/// Returns the outcomes of the runs that failed in these stages (the caller's record of failures).
/// The seeds of earlier stages are only read back when `sweep` has a cache; without one they run
/// again.
std::vector<RunOutcome> grow_to_target(const std::vector<StagedList>& lists,
                                       const SweepOptions& sweep, const WindowRule& window);

}  // namespace molchaos::validation
