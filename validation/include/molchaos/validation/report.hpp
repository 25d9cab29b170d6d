// Writing the reproduction out: results/REPORT.md (every table behind every figure, and each
// claim of the paper with its verdict), results/fig4_A_of_eps.csv and results/a2_of_eps.csv. Files
// are written to a temporary name and renamed.
#pragma once

#include <string>
#include <vector>

#include "molchaos/validation/reproduce.hpp"

namespace molchaos::validation {

/// Writes `text` to path through sim::write_file_atomically, creating the parent folder first.
void write_file_atomically(const std::string& path, const std::string& text);

/// The '#' lines of the options that re-run a table of the reproduction, which `reproduce
/// --config TABLE` reads back: quick, seeds and base_seed, the options that change what the tables
/// hold.
std::string rerun_lines(const ReproduceConfig& config);

/// csv with `lines` put after its title (first) line.
std::string after_title(std::string csv, const std::string& lines);

/// Fig. 4's data, every point: columns density,restitution,randomize,A,A_err,runs,A_theory,
/// A_theory_err,a2,a2_err,mean_dyad,mean_dyad_err,breakdowns; `randomize` is the MD gas's mode
/// (none, paper, flux) or `dsmc` for the DSMC gas.
std::string fig4_csv(const ReproduceResults& results);

/// The straight-line fits A = intercept + slope·ε of Fig. 4, one row per gas: columns
/// density,randomize,intercept,intercept_err,slope,slope_err,chi2_per_dof,points,
/// slope_err_over_seeds (the jackknife over seeds; nan with one seed per point).
std::string fig4_fits_csv(const ReproduceResults& results);

/// a2(ε) of every gas and of the Sonine theory, one row per point: columns
/// dimension,density,restitution,source,a2,a2_err; `source` is the gas (none, paper, flux, dsmc)
/// or the theory (first_sonine, a2_a3).
std::string a2_csv(const ReproduceResults& results);

/// One sentence on what the figure in `file` (e.g. "fig3_temperature.png") shows and what to look
/// at; empty for a figure the report does not know.
std::string figure_caption(const std::string& file, const ReproduceResults& results);

/// "value ± error" to `decimals` decimals; the value alone where the error is unknown (nan, or 0:
/// a mean over fewer than two runs holds 0, whose error is not zero but unknown).
std::string with_error(double value, double error, int decimals);

/// A claim can be decided only on simulated values that carry a standard error. Where one of its
/// comparison rows compares a simulated value without one (a mean over fewer than two runs, which
/// holds the error 0: one seed per point) with theory, another gas or the paper, the claim's
/// verdict becomes "not decided", its deciding text says why, and each such row's verdict too,
/// with no difference in standard errors. Claims resting on theory alone, on a χ² statistic or on
/// runs of their own with errors keep theirs.
/// `seeds` is the seeds per point the reproduction ran (for the wording).
void withhold_undecidable_verdicts(std::vector<Claim>& claims, int seeds);

/// The Markdown report. `figures` lists the figure files (relative to the report) to embed;
/// `command` is the command line that produced it.
std::string report_markdown(const ReproduceResults& results,
                            const std::vector<std::string>& figures, const std::string& command);

}  // namespace molchaos::validation
