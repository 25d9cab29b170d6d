// Atomic file replacement and the clean-up of temporaries left by killed writers.
#include "molchaos/sim/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>

namespace molchaos::sim {
namespace {

namespace fs = std::filesystem;
constexpr const char* k_marker = ".molchaos-tmp.";

std::string host_name() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
  std::string host(name);
  for (char& c : host)
    if (c == '.' || c == '/') c = '_';  // keeps the name's fields separable
  return host;
}

std::string error_text(int error) { return std::strerror(error); }

// The longest file name, in bytes, that the file system of path's directory takes.
std::size_t name_max(const fs::path& path) {
  const fs::path directory = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  const long max = ::pathconf(directory.c_str(), _PC_NAME_MAX);
  return max > 0 ? static_cast<std::size_t>(max) : NAME_MAX;
}

}  // namespace

std::string temporary_name(const std::string& path) {
  static thread_local std::mt19937_64 random{std::random_device{}()};
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(random()));
  std::string suffix = k_marker;  // appended piecewise (GCC 12 warns falsely on literal + string)
  suffix += host_name();
  suffix += '.';
  suffix += std::to_string(::getpid());
  suffix += '.';
  suffix += hex;
  const fs::path p(path);
  std::string stem = p.filename().string();
  // Any name the file system takes must leave room for the suffix: the stem is cut, at the start
  // of a UTF-8 character, so that the temporary's name fits the longest name and its path the
  // longest path (PATH_MAX bytes with the terminating zero), as the final name does.
  const std::size_t directory = p.parent_path().empty() ? 0 : p.parent_path().string().size() + 1;
  const std::size_t path_room = PATH_MAX - 1 > directory ? PATH_MAX - 1 - directory : 0;
  const std::size_t max = std::min(name_max(p), path_room);
  const std::size_t room = max > suffix.size() + 1 ? max - suffix.size() - 1 : 0;
  if (stem.size() > room) {
    std::size_t cut = room;
    while (cut > 0 && (static_cast<unsigned char>(stem[cut]) & 0xC0) == 0x80) --cut;
    stem.resize(cut);
  }
  std::string name = ".";
  name += stem;
  name += suffix;
  return (p.parent_path() / name).string();
}

StagedFiles::~StagedFiles() {
  for (const auto& [temporary, path] : staged_) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
  }
}

std::string StagedFiles::temporary(const std::string& path) {
  staged_.emplace_back(temporary_name(path), path);
  return staged_.back().first;
}

void StagedFiles::write(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string file = temporary(path);
  auto fail = [&](const std::string& what, int error) {
    throw std::runtime_error("cannot write " + path + ": " + what +
                             (error ? " (" + error_text(error) + ")" : std::string()));
  };
  errno = 0;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) fail("cannot create " + file, errno);
  errno = 0;
  try {
    write(out);
  } catch (const std::exception& e) {
    fail(e.what(), 0);
  }
  if (!out) fail("write failed", errno);  // errno of the write that failed (e.g. ENOSPC)
  out.flush();
  if (!out) fail("write failed", errno);
  out.close();
  if (out.fail()) fail("close failed", errno);
}

void StagedFiles::commit() {
  // Every name first, so that a name taken meanwhile by a directory or a special file (which a
  // rename cannot replace, or should not) stops the set before any file of it is in place.
  for (const auto& [temporary, path] : staged_) {
    std::error_code ec;
    const auto status = fs::symlink_status(path, ec);
    if (fs::is_directory(status))  // as the rename would say
      throw std::runtime_error("cannot write " + path + ": rename failed (" + error_text(EISDIR) +
                               ")");
    if (fs::exists(status) && !fs::is_regular_file(status))
      throw std::runtime_error("cannot write " + path + ": not a regular file any more");
  }
  while (!staged_.empty()) {
    const auto& [temporary, path] = staged_.front();
    if (::rename(temporary.c_str(), path.c_str()) != 0)
      throw std::runtime_error("cannot write " + path + ": rename failed (" + error_text(errno) +
                               ")");
    staged_.erase(staged_.begin());
  }
}

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  StagedFiles file;
  file.write(path, write);
  file.commit();
}

void probe_writable(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw std::runtime_error("'" + path + "' is a directory");
  if (const auto status = fs::symlink_status(path, ec);
      fs::exists(status) && !fs::is_regular_file(status))
    throw std::runtime_error("'" + path +
                             "' exists and is not a regular file (a device, FIFO, socket or "
                             "symlink); give a new name or a regular file");
  // The temporary's name is cut to fit (temporary_name()), so a name too long is caught here.
  const std::size_t bytes = fs::path(path).filename().string().size(), most = name_max(path);
  if (bytes > most)
    throw std::runtime_error("cannot create " + path + ": its name is " + std::to_string(bytes) +
                             " bytes, the file system takes at most " + std::to_string(most) +
                             " (" + error_text(ENAMETOOLONG) + ")");
  const std::string temporary = temporary_name(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0)
    throw std::runtime_error("cannot create a file next to " + path + ": " + error_text(errno));
  ::close(fd);
  ::unlink(temporary.c_str());
}

void remove_stale_temporaries(const std::string& directory, double min_age_seconds) {
  std::error_code ec;
  if (directory.empty() || !fs::is_directory(directory, ec)) return;
  const std::string host = host_name();
  const auto now = fs::file_time_type::clock::now();
  for (const auto& entry : fs::directory_iterator(directory, ec)) {
    const std::string name = entry.path().filename().string();
    const auto at = name.find(k_marker);
    if (name.empty() || name[0] != '.' || at == std::string::npos) continue;
    // Fields after the marker: host, pid, 16 hex digits; anything else is not ours.
    const std::string rest = name.substr(at + std::strlen(k_marker));
    const auto dot2 = rest.rfind('.');
    const auto dot1 = dot2 == std::string::npos ? dot2 : rest.rfind('.', dot2 - 1);
    if (dot1 == std::string::npos || rest.size() - dot2 - 1 != 16) continue;
    const std::string writer_host = rest.substr(0, dot1);
    const std::string pid_text = rest.substr(dot1 + 1, dot2 - dot1 - 1);
    // A process id has at most 7 digits (Linux's pid_max is at most 2^22): a longer one is not
    // ours (and would not fit the int that kill() takes).
    if (pid_text.empty() || pid_text.size() > 7 ||
        pid_text.find_first_not_of("0123456789") != std::string::npos)
      continue;
    if (rest.substr(dot2 + 1).find_first_not_of("0123456789abcdef") != std::string::npos) continue;
    const auto modified = fs::last_write_time(entry.path(), ec);
    if (ec) continue;
    const double age = std::chrono::duration<double>(now - modified).count();
    if (age < min_age_seconds) continue;
    // kill() fails with EPERM for a live process of another user: alive all the same.
    const bool writer_alive =
        writer_host == host && (::kill(std::stoi(pid_text), 0) == 0 || errno == EPERM);
    if (writer_alive || (writer_host != host && age < 86400.0)) continue;
    fs::remove_all(entry.path(), ec);  // a staging folder of several outputs, too
  }
}

}  // namespace molchaos::sim
