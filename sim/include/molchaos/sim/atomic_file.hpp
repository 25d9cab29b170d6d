// Writing a file so that readers see the old file or the whole new one, never a part: write to a
// temporary name next to it, check every write and the close, then rename. On failure the
// temporary is removed and the error names the file and the reason (e.g. "No space left").
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace molchaos::sim {

/// Temporary name for `path`: ".<name>.molchaos-tmp.<host>.<pid>.<random hex>" in its directory.
/// Only names of this form are ever removed by remove_stale_temporaries().
std::string temporary_name(const std::string& path);

/// Writes what `write` puts into the stream to `path` atomically; throws std::runtime_error.
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write);

/// Throws std::runtime_error unless a temporary file can be created (and is removed again) next to
/// `path`: run before any long work so that an unwritable output fails at once.
void probe_writable(const std::string& path);

/// Removes this suite's temporary files in `directory` older than `min_age_seconds` whose writer
/// is gone (same host, dead PID) or that are older than a day (another host or PID namespace).
void remove_stale_temporaries(const std::string& directory, double min_age_seconds = 3600.0);

}  // namespace molchaos::sim
