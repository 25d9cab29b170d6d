// Writing a file so that readers see the old file or the whole new one, never a part: write to a
// temporary name next to it, check every write and the close, then rename (several files as one:
// all renamed once all are written). On failure the temporaries are removed and the error names
// the file and the reason (e.g. "No space left").
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace molchaos::sim {

/// Temporary name for `path`: ".<name>.molchaos-tmp.<host>.<pid>.<random hex>" in its directory,
/// <name> cut short where the whole would be longer than the file system takes.
/// Only names of this form are ever removed by remove_stale_temporaries().
std::string temporary_name(const std::string& path);

/// Several files written as one output: each to a temporary name beside it (write(), or for a
/// writer that makes the file itself, the name temporary() gives), then all renamed to their
/// names by commit() once every one is complete. Until then, and on any failure, no named file is
/// touched, and the destructor removes the temporaries: a run's outputs appear together or not
/// at all, and a full disk leaves the files of the run before in place.
class StagedFiles {
 public:
  StagedFiles() = default;
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;
  ~StagedFiles();

  /// Writes what `write` puts into the stream to path's temporary; throws std::runtime_error
  /// naming path and the reason (e.g. "No space left on device").
  void write(const std::string& path, const std::function<void(std::ostream&)>& write);
  /// A temporary name for path, renamed to path by commit() (a writer that opens files itself).
  std::string temporary(const std::string& path);
  /// Renames every temporary to its file, in the order staged, once every name is found free or
  /// a regular file (a rename failing after that, rare, leaves the set part renamed); throws
  /// std::runtime_error.
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> staged_;  // (temporary, path)
};

/// Writes what `write` puts into the stream to `path` atomically; throws std::runtime_error.
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write);

/// Throws std::runtime_error unless `path` can take a file written atomically: it is no directory,
/// not an existing non-regular file (a device, FIFO, socket or symlink, which the rename would
/// replace), its name is not longer than the file system takes, and a temporary file can be
/// created (and is removed again) next to it. Run before any long work so that an unwritable
/// output fails at once.
void probe_writable(const std::string& path);

/// Removes this suite's temporary files (and staging folders) in `directory` older than
/// `min_age_seconds` whose writer is gone (same host, dead PID) or that are older than a day
/// (another host or PID namespace).
void remove_stale_temporaries(const std::string& directory, double min_age_seconds = 3600.0);

}  // namespace molchaos::sim
