// Messages of the master–worker protocol as byte strings: a job (run index + every parameter,
// doubles bit for bit) and a result (run index + the run's CSV text, or the error). Ranks are
// assumed to share byte order and type sizes (any real cluster does).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "molchaos/sim/parameters.hpp"

namespace molchaos::mpi {

/// MPI tags of the protocol.
enum class Tag : int { job = 1, result = 2, stop = 3 };

struct JobMessage {
  std::uint64_t index = 0;  ///< position of the run in the sweep
  sim::Parameters parameters;
};

struct ResultMessage {
  std::uint64_t index = 0;
  bool ok = false;
  std::string text;  ///< ok: the run as write_csv wrote it; otherwise the error message
};

std::string encode(const JobMessage& job);
std::string encode(const ResultMessage& result);
/// Both throw std::runtime_error on a truncated or malformed message.
JobMessage decode_job(std::string_view bytes);
ResultMessage decode_result(std::string_view bytes);

}  // namespace molchaos::mpi
