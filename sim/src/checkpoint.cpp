// The checkpoint file: a text head (magic line, format, description of the run) ended by an empty
// line, then the payload's size, the payload and the checksum (FNV-1a, 64 bit) of all before it,
// head included: a head edited to other parameters would otherwise resume the state under them.
// The head can be read with `head`; the payload is the memory image of the run's state.
#include "molchaos/sim/checkpoint.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/version.hpp"

namespace molchaos::sim {
namespace {

// FNV-1a of bytes, continuing from `hash` (the offset basis for a new hash).
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash = 0xcbf29ce484222325ULL) {
  for (const char c : bytes) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return hash;
}

// "key = value" lines up to the first empty line, from `at` on; `at` ends past that line.
std::map<std::string, std::string> read_head(const std::string& text, std::size_t& at,
                                             const std::string& path) {
  std::map<std::string, std::string> head;
  for (;;) {
    const std::size_t end = text.find('\n', at);
    if (end == std::string::npos) throw CheckpointError("checkpoint " + path + ": truncated head");
    const std::string line = text.substr(at, end - at);
    at = end + 1;
    if (line.empty()) return head;
    const std::size_t eq = line.find(" = ");
    if (eq == std::string::npos)
      throw CheckpointError("checkpoint " + path + ": corrupt head line '" + line + "'");
    head[line.substr(0, eq)] = line.substr(eq + 3);
  }
}

}  // namespace

std::string checkpoint_description(const Parameters& p, const std::string& layout) {
  std::string text = "version = " + std::string(k_version) + "\nlayout = " + layout + "\n";
  for (const ParameterInfo& info : parameter_table())
    text += std::string(info.name) + " = " + format_value(p, info) + "\n";
  return text;
}

void write_checkpoint_file(const std::string& path, const Parameters& p, const std::string& layout,
                           const std::string& payload) {
  const std::uint64_t size = payload.size();
  std::string head = std::string(k_checkpoint_magic) +
                     "format = " + std::to_string(k_checkpoint_format) + "\n" +
                     checkpoint_description(p, layout) + "\n";
  head.append(reinterpret_cast<const char*>(&size), sizeof size);
  const std::uint64_t checksum = fnv1a(payload, fnv1a(head));
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(head.data(), static_cast<std::streamsize>(head.size()));
    out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
    out.write(reinterpret_cast<const char*>(&checksum), sizeof checksum);
  });
}

std::map<std::string, std::string> checkpoint_head(const std::string& text,
                                                   const std::string& path) {
  if (!text.starts_with(k_checkpoint_magic))
    throw CheckpointError("checkpoint " + path + ": not a molchaos checkpoint");
  std::size_t at = k_checkpoint_magic.size();
  return read_head(text, at, path);
}

Parameters checkpoint_parameters(const std::string& path) {
  auto refuse = [&](const std::string& what) -> CheckpointError {
    return CheckpointError("checkpoint " + path + ": " + what);
  };
  std::ifstream in(path, std::ios::binary);
  if (std::error_code ec; !std::filesystem::is_regular_file(path, ec) || !in)
    throw refuse("cannot open");
  // The head is a few hundred bytes; 64 KiB holds it with room for long snapshot lists.
  std::string text(std::size_t{1} << 16, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  const std::map<std::string, std::string> head = checkpoint_head(text, path);
  Parameters p;
  for (const ParameterInfo& info : parameter_table()) {
    const auto it = head.find(std::string(info.name));
    if (it == head.end()) throw refuse("no '" + std::string(info.name) + "' in the head");
    try {
      parse_value(p, info, it->second);
    } catch (const std::invalid_argument& e) {
      throw refuse(e.what());
    }
  }
  return p;
}

CheckpointReader read_checkpoint_file(const std::string& path, const Parameters& p,
                                      const std::string& layout, double* saved_t_end) {
  auto refuse = [&](const std::string& what) -> CheckpointError {
    return CheckpointError("checkpoint " + path + ": " + what);
  };
  // A folder opens as a stream but fails at the first read with the library's words.
  if (std::error_code ec; !std::filesystem::is_regular_file(path, ec)) throw refuse("not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw refuse("cannot open");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string magic(k_checkpoint_magic);
  if (text.compare(0, magic.size(), magic) != 0) throw refuse("not a molchaos checkpoint");
  std::size_t at = magic.size();
  std::map<std::string, std::string> head = read_head(text, at, path);
  auto field = [&](const std::string& key) -> std::string {
    const auto it = head.find(key);
    if (it == head.end()) throw refuse("no '" + key + "' in the head");
    return it->second;
  };
  auto differs = [&](const std::string& key, const std::string& theirs, const std::string& ours) {
    return refuse(key + " differs: checkpoint " + theirs + ", this run " + ours);
  };
  // In order: what makes the rest unreadable first (another format or build), then the
  // checksum, which covers the head too: an edited head is refused as edited before its values
  // are compared with this run's.
  if (field("format") != std::to_string(k_checkpoint_format))
    throw differs("format", field("format"), std::to_string(k_checkpoint_format));
  if (field("version") != k_version)
    throw refuse("written by molchaos " + field("version") + ", this is " + k_version +
                 " (a restart is exact only with the build that wrote the checkpoint)");
  std::uint64_t size = 0, checksum = 0;
  if (text.size() - at < 2 * sizeof size) throw refuse("truncated payload");
  std::memcpy(&size, text.data() + at, sizeof size);
  at += sizeof size;
  if (size != text.size() - at - sizeof checksum)
    throw refuse(size > text.size() - at - sizeof checksum
                     ? "truncated payload"
                     : "bytes after the checksum (the file was extended)");
  std::memcpy(&checksum, text.data() + at + size, sizeof checksum);
  if (checksum != fnv1a(std::string_view(text).substr(0, at + size)))
    throw refuse("checksum mismatch (corrupt or edited file)");
  const ParameterInfo& dimension = *find_parameter("dimension");
  if (field("dimension") != format_value(p, dimension))
    throw differs("dimension", field("dimension"), format_value(p, dimension));
  for (const ParameterInfo& info : parameter_table()) {
    const std::string key(info.name), ours = format_value(p, info);
    if (key == "t_end") continue;  // may change: checked by run() against the checkpoint's time
    if (field(key) != ours)
      throw refuse("parameter " + key + " differs: checkpoint " + field(key) + ", this run " +
                   ours + " (only t_end may change on a restart)");
  }
  if (field("layout") != layout) throw differs("layout", field("layout"), layout);
  Parameters saved = p;
  try {
    parse_value(saved, *find_parameter("t_end"), field("t_end"));
  } catch (const std::invalid_argument& e) {
    throw refuse(e.what());
  }
  *saved_t_end = saved.t_end;

  std::string payload = text.substr(at, static_cast<std::size_t>(size));
  return CheckpointReader(std::move(payload), path);
}

bool is_checkpoint_file(const std::string& path) {
  std::error_code ec;
  if (path.empty() || !std::filesystem::is_regular_file(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  std::string start(k_checkpoint_magic.size(), '\0');
  in.read(start.data(), static_cast<std::streamsize>(start.size()));
  return in && start == k_checkpoint_magic;
}

void require_replaceable_by_checkpoint(const std::string& path, const std::string& restart) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty() || !fs::is_regular_file(path, ec) || fs::file_size(path, ec) == 0) return;
  if (!is_checkpoint_file(path))
    throw std::invalid_argument(path +
                                " holds a file that is no molchaos checkpoint, which the first "
                                "checkpoint would replace: choose another name, or remove that "
                                "file");
  // A checkpoint is a run's only way on: replaced by a run that does not continue it (another
  // run, or the same command started afresh), its progress would be lost without a word.
  if (restart.empty() || !fs::equivalent(path, restart, ec))
    throw std::invalid_argument(
        path +
        " holds the checkpoint of a run that this run does not continue, "
        "which the first checkpoint would replace: restart from it to continue "
        "that run, or choose another name, or remove that file");
}

}  // namespace molchaos::sim
