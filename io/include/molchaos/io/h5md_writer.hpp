// The snapshots of a run as an H5MD 1.1 trajectory (HDF5): particles/all/{position,velocity} with
// value/time/step, the periodic box, and the run's parameters as attributes of /parameters.
#pragma once

#include <string>

#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/result.hpp"

namespace molchaos::io {

/// Writes every snapshot of r to path (temporary file, then rename). step is the number of
/// collisions since t = 0: an event-driven run has no time step. /h5md/author's name is the
/// environment variable MOLCHAOS_AUTHOR ("unknown" without it). Throws std::runtime_error on an
/// HDF5 failure.
void write_h5md_file(const sim::RunResult& r, const std::string& path);
/// The same, staged in `files` (renamed to path by files.commit(), with a run's other outputs).
void write_h5md_file(const sim::RunResult& r, const std::string& path, sim::StagedFiles& files);

}  // namespace molchaos::io
