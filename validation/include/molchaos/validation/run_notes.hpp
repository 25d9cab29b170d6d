// Why runs of a state point gave no value (a run too short for its transient, an elastic run
// without a collision, a failed run), grouped by reason: a sweep over many seeds that share a
// reason says it once, with how many runs and which seeds.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace molchaos::validation {

struct RunNote {
  std::string reason;
  /// The run's seed; empty where the reason names the run itself (a failed run's error).
  std::optional<std::uint64_t> seed;
};

/// One line per distinct reason, in the order of first appearance: "seed S: reason" for one run,
/// "N runs (seeds S1, S2, S3 and K more): reason" for several.
std::vector<std::string> note_lines(const std::vector<RunNote>& notes);

}  // namespace molchaos::validation
