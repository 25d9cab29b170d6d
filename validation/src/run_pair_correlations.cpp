#include "molchaos/validation/run_pair_correlations.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "molchaos/sim/csv.hpp"
#include "molchaos/validation/pair_correlations.hpp"

namespace molchaos::validation {

double collisions_per_particle_at(const sim::RunResult& run, double t) {
  const auto& s = run.samples;
  const double n = static_cast<double>(run.parameters.particles);
  for (std::size_t k = 1; k < s.size(); ++k)
    if (s[k].t >= t) {
      const double w = (t - s[k - 1].t) / (s[k].t - s[k - 1].t);
      return 2.0 / n *
             ((1 - w) * static_cast<double>(s[k - 1].collisions) + w * double(s[k].collisions));
    }
  return s.empty() ? 0.0 : 2.0 * static_cast<double>(s.back().collisions) / n;
}

void write_run_pair_correlations(const sim::RunResult& run, std::ostream& out) {
  if (run.parameters.snapshot_times.empty())
    throw std::invalid_argument(
        "pair correlations: the run has no snapshot times (give --snapshot-times)");
  const int d = run.parameters.dimension;
  out << sim::k_run_title
      << ": pair correlation functions of the snapshots, c = v/sqrt(2T) at the snapshot's T; "
         "errors of one snapshot\n"
      << "# version = " << run.version << "\n";
  sim::write_parameter_lines(run.parameters, out);
  // A run that stopped before its first snapshot time (a stop condition, a collapse) measured
  // nothing: the table says so instead of the run losing its other outputs.
  if (run.snapshots.empty())
    out << "# no rows: the run stopped before its first snapshot time (" << sim::stop_message(run)
        << ")\n";
  out << "t,tau,side,r_lo,r_hi,g,g_err,G_par,G_par_err,G_perp,G_perp_err,pairs\n";
  for (const auto& snap : run.snapshots) {
    const double tau = collisions_per_particle_at(run, snap.t);
    for (const auto& b : combine_pair_sums({pair_sums(snap, d, default_pair_grid(snap.box))}, d))
      out << fmt::format("{},{:.6g},{},{},{},{:.6g},{:.3g},{:.5g},{:.3g},{:.5g},{:.3g},{}\n",
                         snap.t, tau, to_string(b.side), b.r_lo, b.r_hi, b.g.value, b.g.error,
                         b.G_par.value, b.G_par.error, b.G_perp.value, b.G_perp.error, b.pairs);
  }
}

}  // namespace molchaos::validation
