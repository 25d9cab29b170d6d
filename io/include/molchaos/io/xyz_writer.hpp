// The snapshots of a run as extended XYZ frames (box in Lattice, species/pos/vel properties), the
// single-configuration format that OVITO and ASE open. Disks (d = 2) are written with z = 0.
#pragma once

#include <ostream>
#include <string>

#include "molchaos/sim/result.hpp"

namespace molchaos::io {

/// One frame: particle count, comment line with Lattice, Properties, pbc and Time, then the rows.
void write_xyz_frame(const sim::Snapshot& snapshot, int dimension, std::ostream& out);

/// All snapshots of r, one frame each, to path (temporary file, then rename).
void write_xyz_file(const sim::RunResult& r, const std::string& path);

}  // namespace molchaos::io
