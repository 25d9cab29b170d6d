// The result file: '# key = value' header lines (every parameter, version, stop reason, counts),
// then one row per sample. Numbers are written in shortest round-trip form, so a file read back
// gives the same doubles and the same seed gives a byte-identical file.
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include "molchaos/sim/result.hpp"

namespace molchaos::sim {

/// How the title line of a run's own result files begins (its CSV and pair-correlation table):
/// `--config` takes a header that begins so for a whole run's, which names every parameter.
inline constexpr std::string_view k_run_title = "# molchaos simulate";

void write_csv(const RunResult& result, std::ostream& out);
/// The parameter lines of a result file's header, "# <name> = <value>" per row of the parameter
/// table (rows at an omitted default left out): what `--config FILE` reads back.
void write_parameter_lines(const Parameters& p, std::ostream& out);
/// Writes to a temporary file next to path, then renames: never a half-written file at path.
void write_csv_file(const RunResult& result, const std::string& path);
/// Parses what write_csv wrote; throws std::runtime_error on a corrupt or truncated file.
RunResult read_csv_file(const std::string& path);
RunResult read_csv(std::istream& in);

/// Snapshot `index` of a run as CSV: the run's version and parameters (so that the file can be
/// re-run, `simulate --config`), its time, box side and collisions since t = 0, then
/// x,y[,z],vx,vy[,vz] per particle.
void write_snapshot_csv(const RunResult& r, std::size_t index, std::ostream& out);

}  // namespace molchaos::sim
