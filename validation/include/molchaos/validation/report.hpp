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

/// Fig. 4's data, every point: columns density,restitution,randomize,A,A_err,runs,A_theory,
/// A_theory_err,a2,a2_err,mean_dyad,mean_dyad_err,breakdowns; `randomize` is the MD gas's mode
/// (none, paper, flux) or `dsmc` for the DSMC gas.
std::string fig4_csv(const ReproduceResults& results);

/// a2(ε) of every gas and of the Sonine theory, one row per point: columns
/// dimension,density,restitution,source,a2,a2_err; `source` is the gas (none, paper, flux, dsmc)
/// or the theory (first_sonine, a2_a3).
std::string a2_csv(const ReproduceResults& results);

/// One sentence on what the figure in `file` (e.g. "fig3_temperature.png") shows and what to look
/// at; empty for a figure the report does not know.
std::string figure_caption(const std::string& file, const ReproduceResults& results);

/// The Markdown report. `figures` lists the figure files (relative to the report) to embed;
/// `command` is the command line that produced it.
std::string report_markdown(const ReproduceResults& results,
                            const std::vector<std::string>& figures, const std::string& command);

}  // namespace molchaos::validation
