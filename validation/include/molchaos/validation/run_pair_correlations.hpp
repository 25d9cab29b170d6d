// The pair correlation functions of one run's snapshots as a table, one row per snapshot, side
// and r-bin: what `molchaos simulate --pair-correlations FILE` writes beside the run. The errors
// are one snapshot's (independent pair products, exact under molecular chaos); errors over runs
// come from the correlation study (correlation_study.hpp).
#pragma once

#include <ostream>

#include "molchaos/sim/result.hpp"

namespace molchaos::validation {

/// Collisions per particle at time t, interpolated linearly between the run's samples.
double collisions_per_particle_at(const sim::RunResult& run, double t);

/// Header (what ran, its parameters: `--config FILE` repeats the run), then the table
/// t,tau,side,r_lo,r_hi,g,g_err,G_par,G_par_err,G_perp,G_perp_err,pairs.
/// Throws std::invalid_argument if the run has no snapshots.
void write_run_pair_correlations(const sim::RunResult& run, std::ostream& out);

}  // namespace molchaos::validation
