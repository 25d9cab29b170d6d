// The snapshots of a run as extended XYZ frames (box in Lattice, species/pos/vel/momenta
// properties, momenta = vel at m = 1 for ASE), the single-configuration format that OVITO and ASE
// open. Disks (d = 2) are written with z = 0.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>

#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/result.hpp"

namespace molchaos::io {

/// Frame `index` of r: particle count, a comment line with Lattice, Properties, Time,
/// Collisions, pbc and the run's parameters (their table names, a list quoted: the file can be
/// re-run, `simulate --config run.xyz`), then the rows.
void write_xyz_frame(const sim::RunResult& r, std::size_t index, std::ostream& out);

/// All snapshots of r, one frame each, to path (temporary file, then rename).
void write_xyz_file(const sim::RunResult& r, const std::string& path);
/// The same, staged in `files` (renamed to path by files.commit(), with a run's other outputs).
void write_xyz_file(const sim::RunResult& r, const std::string& path, sim::StagedFiles& files);

}  // namespace molchaos::io
