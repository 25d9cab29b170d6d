// Checkpoints of a run: the file format (magic, format version, a text description of the run's
// parameters, a binary payload and its checksum) and the byte archives with which the engine and
// run() write and read their state. A checkpoint holds everything that the parameters do not fix,
// bit for bit, so that a restarted run writes the same bytes as the uninterrupted one. The payload
// is the memory image of the engine's arrays: it is read back by the same molchaos build (the
// description names the version, and a checkpoint of another is refused).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "molchaos/sim/parameters.hpp"

namespace molchaos::sim {

/// Increase whenever the payload changes (members added, removed, reordered, or their meaning).
inline constexpr std::uint32_t k_checkpoint_format = 7;
/// The first line of a checkpoint file; "key = value" lines follow (format, version, layout and
/// every parameter), up to an empty line.
inline constexpr std::string_view k_checkpoint_magic = "molchaos checkpoint\n";

/// A checkpoint that cannot be used for this run: unreadable, corrupt, of another format, version,
/// dimension or parameters. The message names the file and what differs.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What a run did about its periodic checkpoints (those at an interval), filled in by run().
struct CheckpointRecord {
  std::size_t due = 0;  ///< periodic checkpoints due (at the intervals), written or not
  double start = 0;     ///< the time the run started from (0, or a restart's checkpoint time)
  /// The longest --checkpoint-interval at which this run would have taken one: the last sample
  /// time before its end less `start` (0: it reached no such time).
  double longest_interval = 0;
};

/// What run() does about checkpoints (all off by default).
struct CheckpointOptions {
  std::string path;          ///< checkpoint file written (empty: none)
  double interval = 0;       ///< simulated time between checkpoints (0: none)
  double wall_interval = 0;  ///< wall-clock seconds between checkpoints (0: none)
  std::string restart;       ///< checkpoint to continue from (empty: a new run)
  /// Set (by a signal handler) to ask for a checkpoint and a return without a result.
  const std::atomic<bool>* interrupt = nullptr;
  /// Set by the run once its relaxation (or the restore of a checkpoint) is done, from when an
  /// interrupt is obeyed. The relaxation neither pauses nor can be saved: a signal handler ends
  /// the process at once before then.
  std::atomic<bool>* under_way = nullptr;
  /// Called, with the run's time and the reason, when a periodic checkpoint (interval or wall
  /// clock) cannot be written (a full disk); the run then goes on, as its result does not depend
  /// on the checkpoint, and the file keeps the last checkpoint written, whole (the write is
  /// atomic). Empty: the error ends the run. A checkpoint an interrupt asks for is the run's
  /// only copy, and its failure always ends the run.
  std::function<void(double time, const std::string& reason)> write_failed;
  /// Filled in by the run, if set.
  CheckpointRecord* record = nullptr;

  /// A file named but no interval: checkpoints are written only on an interrupt, so a run that
  /// finishes leaves none (which the CLI notes and Python warns of).
  [[nodiscard]] bool only_on_interrupt() const {
    return !path.empty() && interval == 0 && wall_interval == 0;
  }
};

namespace detail {
template <class T>
struct is_vector : std::false_type {};
template <class T, class A>
struct is_vector<std::vector<T, A>> : std::true_type {};
}  // namespace detail

/// Appends values to a byte buffer: trivially copyable values as their bytes, vectors of them as
/// their length and their elements. Used with the same member lists as CheckpointReader.
class CheckpointWriter {
 public:
  static constexpr bool reading = false;
  template <class... T>
  void operator()(const T&... values) {
    (put(values), ...);
  }
  void bytes(const void* data, std::size_t size) {
    data_.append(static_cast<const char*>(data), size);
  }
  const std::string& data() const { return data_; }

 private:
  template <class T>
  void put(const T& value) {
    if constexpr (detail::is_vector<T>::value) {
      static_assert(std::is_trivially_copyable_v<typename T::value_type>);
      put(static_cast<std::uint64_t>(value.size()));
      bytes(value.data(), value.size() * sizeof(typename T::value_type));
    } else {
      static_assert(std::is_trivially_copyable_v<T>);
      bytes(&value, sizeof value);
    }
  }
  std::string data_;
};

/// Reads back what CheckpointWriter wrote, in the same order; throws CheckpointError when the
/// payload ends early or a vector is longer than what is left.
class CheckpointReader {
 public:
  static constexpr bool reading = true;
  explicit CheckpointReader(std::string data, std::string origin)
      : data_(std::move(data)), origin_(std::move(origin)) {}
  template <class... T>
  void operator()(T&... values) {
    (get(values), ...);
  }
  void bytes(void* data, std::size_t size) {
    if (size > data_.size() - at_) fail("payload ends early");
    std::memcpy(data, data_.data() + at_, size);
    at_ += size;
  }
  /// Throws unless every byte was read (a payload of another layout).
  void finish() const {
    if (at_ != data_.size()) fail("payload longer than this build's state");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw CheckpointError("checkpoint " + origin_ + ": " + what);
  }

 private:
  template <class T>
  void get(T& value) {
    if constexpr (detail::is_vector<T>::value) {
      using V = typename T::value_type;
      static_assert(std::is_trivially_copyable_v<V>);
      std::uint64_t size = 0;
      get(size);
      if (size > (data_.size() - at_) / sizeof(V)) fail("payload ends early");
      value.resize(static_cast<std::size_t>(size));
      bytes(value.data(), value.size() * sizeof(V));
    } else {
      static_assert(std::is_trivially_copyable_v<T>);
      bytes(&value, sizeof value);
    }
  }
  std::string data_;
  std::string origin_;
  std::size_t at_ = 0;
};

/// The description written at the head of a checkpoint: "key = value" lines for the molchaos
/// version, the payload layout (`layout`, e.g. the engine's record sizes and observer) and every
/// row of the parameter table.
std::string checkpoint_description(const Parameters& p, const std::string& layout);

/// Writes magic, format, description, payload and checksum atomically (write_file_atomically).
void write_checkpoint_file(const std::string& path, const Parameters& p, const std::string& layout,
                           const std::string& payload);

/// Reads a checkpoint for a run with parameters p and payload layout `layout`; throws
/// CheckpointError naming what differs: format, version, layout, dimension, or a parameter.
/// Every parameter must be equal except t_end, which a restart may change (to run on longer, or
/// shorter as long as t_end lies after the checkpoint); run() checks that against the checkpoint's
/// time. Returns the payload, and in *saved_t_end the t_end of the run that wrote it.
CheckpointReader read_checkpoint_file(const std::string& path, const Parameters& p,
                                      const std::string& layout, double* saved_t_end);

/// The "key = value" lines of a checkpoint's head (format, version, layout and every parameter),
/// from `text`, the file or its start; throws CheckpointError naming `path` for a text that is no
/// checkpoint or whose head is cut short or corrupt.
std::map<std::string, std::string> checkpoint_head(const std::string& text,
                                                   const std::string& path);

/// The parameters of the run a checkpoint holds, from its head (a restart's defaults); throws
/// CheckpointError for a file that is not a checkpoint or whose head lacks a parameter or holds a
/// value that does not parse. Neither the ranges nor the checksum are checked here: validate() and
/// the restart do.
Parameters checkpoint_parameters(const std::string& path);

/// Whether `path` is a regular file that opens as a checkpoint (its magic line).
bool is_checkpoint_file(const std::string& path);

/// Refuses (std::invalid_argument, naming the file) a checkpoint path that holds a file the first
/// checkpoint would replace and lose: a file that is no checkpoint and not empty (a result table,
/// notes), or the checkpoint of a run other than the one restarted from `restart` (empty: a new
/// run). Only the checkpoint the run continues may be replaced by its own later ones.
void require_replaceable_by_checkpoint(const std::string& path, const std::string& restart);

}  // namespace molchaos::sim
