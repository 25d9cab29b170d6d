// Shared pieces of the command-line front end: range validators whose messages name the allowed
// range, and the usage-error type that main() turns into exit status 2 with one line on stderr.
#pragma once

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/checkpoint.hpp"
#include "molchaos/sim/parameter_table.hpp"

namespace molchaos::app {

/// Bad input found after parsing (for example a combination of flags). main() prints
/// "molchaos: error: <argument>: <what>" and exits with status 2.
class UsageError : public std::runtime_error {
 public:
  UsageError(const std::string& argument, const std::string& what)
      : std::runtime_error(argument + ": " + what) {}
};

/// A run stopped by a signal after writing its checkpoint: main() prints the message and exits
/// with status 3 (k_exit_interrupted), so that a batch script can tell it from a failure.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
inline constexpr int k_exit_interrupted = 3;

inline std::string format_interval(double lo, bool lo_closed, double hi, bool hi_closed) {
  auto num = [](double x) {
    if (std::isinf(x)) return std::string(x > 0 ? "inf" : "-inf");
    // Shortest faithful form (1e-13, 0.01, 1000000), not std::to_string's six decimals.
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", x);
    return std::string(text);
  };
  return std::string(lo_closed ? "[" : "(") + num(lo) + ", " + num(hi) + (hi_closed ? "]" : ")");
}

/// Characters of `text` that std::strtod reads (0: none). A result that underflows to a subnormal
/// number or zero is still a number (std::stod would call it out of range). Decimal notation
/// only: strtod's hexadecimal floats (0x1p-1) are refused, as the integer options refuse 0x10.
inline std::size_t parse_real(const std::string& text, double& x) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])) ||
      text.find_first_of("xX") != std::string::npos)
    return 0;
  char* end = nullptr;
  x = std::strtod(text.c_str(), &end);
  return static_cast<std::size_t>(end - text.c_str());
}

/// The name of the number validators below, by which a --config file's reader knows an option
/// that takes numbers (a TOML string "100" is no number for it).
inline const std::string k_number_check = "number";

/// The number validators below pass the value on as they read it (integers as plain decimal
/// digits, -0 as 0), so they are attached with ->transform(): ->check() would check a copy.
/// A validator for a real number in an interval; the message names the allowed range.
inline CLI::Validator real_in(double lo, bool lo_closed, double hi, bool hi_closed) {
  const std::string range = format_interval(lo, lo_closed, hi, hi_closed);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double x = 0.0;
        const std::size_t used = parse_real(text, x);
        if (used == 0 || used != text.size() || std::isnan(x))
          return "'" + text + "' is not a number; allowed range " + range;
        // An infinite end of a range is open: "inf" is read, and is out of every range.
        if (std::isinf(x)) return "value " + text + " is not finite; allowed range " + range;
        // A value below the smallest subnormal reads as 0, which can mean something else (tc = 0
        // turns the TC model off): refused, not rounded to 0.
        if (x == 0 && text.substr(0, text.find_first_of("eEpP")).find_first_of("123456789") !=
                          std::string::npos)
          return "value " + text +
                 " is nearer 0 than the smallest double (4.9e-324) and would "
                 "read as 0; allowed range " +
                 range;
        const bool ok_lo = lo_closed ? x >= lo : x > lo;
        const bool ok_hi = hi_closed ? x <= hi : x < hi;
        if (!ok_lo || !ok_hi) return "value " + text + " is outside the allowed range " + range;
        if (x == 0) text = "0";  // -0 is 0: one header line and one cache key for one run
        return {};
      },
      "in " + range, k_number_check);
}

/// A validator for an integer in the closed interval [lo, hi].
inline CLI::Validator integer_in(long long lo, long long hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        long long x = 0;
        std::size_t used = 0;
        const bool spaced = text.empty() || std::isspace(static_cast<unsigned char>(text[0]));
        try {
          if (!spaced) x = std::stoll(text, &used);  // (stoll would skip leading spaces)
        } catch (const std::out_of_range&) {  // digits beyond a 64-bit integer
          return "value " + text + " is outside the allowed range " + range;
        } catch (...) {
          used = 0;
        }
        if (used == 0 || used != text.size())
          return "'" + text + "' is not an integer; allowed range " + range;
        if (x < lo || x > hi) return "value " + text + " is outside the allowed range " + range;
        // Read in base 10 here, but CLI11 converts with base 0, which takes a leading 0 for
        // octal (050 -> 40): the value goes on as plain decimal digits.
        text = std::to_string(x);
        return {};
      },
      "integer in " + range, k_number_check);
}

/// The command-line flag of a field named in a validation message ("t_end: ..." -> "--t-end"):
/// the parameter table's flag, or for the list fields of a sweep the flag of their element.
inline std::string flag_of_field(const std::string& field) {
  if (const sim::ParameterInfo* info = sim::find_parameter(field)) return std::string(info->flag);
  static const std::pair<const char*, const char*> lists[] = {{"densities", "density"},
                                                              {"restitutions", "restitution"},
                                                              {"modes", "randomize"},
                                                              {"methods", "method"}};
  for (const auto& [name, element] : lists)
    if (field == name) return std::string(sim::find_parameter(element)->flag);
  if (field == "t_end_in_tau0") return "--t-end-tau0";
  if (field == "correlation_b") return "--b";  // the theory's name for the ansatz's b
  std::string flag = "--" + field;
  for (char& c : flag)
    if (c == '_') c = '-';
  return flag;
}

/// Rethrows a validation message "<field>: <what>" as the UsageError of the field's flag.
[[noreturn]] inline void throw_as_usage_error(const std::string& context, const std::string& what) {
  const auto colon = what.find(": ");
  if (colon == std::string::npos || what.find(' ') < colon) throw UsageError(context, what);
  throw UsageError(flag_of_field(what.substr(0, colon)), what.substr(colon + 2));
}

/// A validator for an unsigned 64-bit integer (seeds, counts): digits only, no sign.
inline CLI::Validator unsigned_integer() {
  const std::string range = "[0, 18446744073709551615]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const bool digits =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        if (!digits) return "'" + text + "' is not a non-negative integer; allowed range " + range;
        try {
          text = std::to_string(std::stoull(text));  // decimal digits on (see integer_in)
        } catch (...) {
          return "value " + text + " is outside the allowed range " + range;
        }
        return {};
      },
      "integer in " + range, k_number_check);
}

/// A validator for a file or folder name given on the command line or in a --config file: not
/// empty, and not "-". Where the default is an empty name ("no such output"), an empty value typed
/// by hand (an unset shell variable) would otherwise drop the output without a word; "-", which
/// other tools read as standard input or output, would name a file "-".
inline CLI::Validator path_name() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text.empty()) return "empty name; give a path, or leave the option out";
        if (text == "-")
          return "'-' (standard input or output) is not supported; give a file or folder name";
        return "";
      },
      "PATH");
}

/// Throws UsageError(flag, ...) unless `directory` is, or can be created as, a writable
/// directory: checked before any work starts, so a run never ends in "cannot write".
inline void require_writable_directory(const std::string& flag, const std::string& directory) {
  namespace fs = std::filesystem;
  fs::path p = directory.empty() ? fs::path(".") : fs::path(directory);
  std::error_code ec;
  if (fs::exists(p, ec) && !fs::is_directory(p, ec))
    throw UsageError(flag, "'" + directory + "' exists and is not a directory");
  // The nearest existing ancestor must be a directory we may write into.
  fs::path existing = p;
  while (!existing.empty() && !fs::exists(existing, ec)) existing = existing.parent_path();
  if (existing.empty()) existing = ".";
  if (!fs::is_directory(existing, ec))
    throw UsageError(
        flag, "cannot create '" + directory + "': '" + existing.string() + "' is not a directory");
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    throw UsageError(flag, "cannot write into '" + existing.string() + "' (" +
                               (errno == EROFS ? "a read-only file system" : "permission denied") +
                               ")");
}

/// require_writable_directory, then creates the directory and a real file in it (removed again):
/// catches what permissions do not show (/proc, /sys, read-only or full file systems). Returns
/// the directories it created, the deepest first (for a command that removes them again when it
/// ends before writing into them).
inline std::vector<std::string> require_usable_directory(const std::string& flag,
                                                         const std::string& directory) {
  namespace fs = std::filesystem;
  require_writable_directory(flag, directory);
  std::error_code ec;
  std::vector<std::string> created;
  for (fs::path p = directory; !p.empty() && !fs::exists(p, ec); p = p.parent_path())
    created.push_back(p.string());
  fs::create_directories(directory, ec);
  if (ec) throw UsageError(flag, "cannot create '" + directory + "': " + ec.message());
  try {
    sim::probe_writable((fs::path(directory) / "probe").string());
  } catch (const std::exception& e) {
    throw UsageError(flag, e.what());
  }
  return created;
}

/// Throws UsageError(flag, ...) unless a file can be written at `path`: its directory exists (or,
/// with `create_parent`, is created here, and a file written in it: permissions do not show /proc
/// to root) and is writable, and `path` is not a directory or special file.
inline void require_writable_file(const std::string& flag, const std::string& path,
                                  bool create_parent) {
  namespace fs = std::filesystem;
  if (path.empty()) throw UsageError(flag, "empty file name");
  const auto probe = [&] {
    try {
      sim::probe_writable(path);  // no directory or special file; /proc, /sys and over-long names
    } catch (const std::exception& e) {  // fail now
      throw UsageError(flag, e.what());
    }
  };
  std::error_code ec;
  // A path that exists and is no regular file first (a directory, a FIFO: the file is replaced by
  // rename), so that the message names it rather than its directory.
  if (const auto status = fs::symlink_status(path, ec);
      fs::exists(status) && !fs::is_regular_file(status))
    probe();
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::exists(parent, ec)) {
    if (!create_parent)
      throw UsageError(flag, "directory '" + parent.string() + "' does not exist");
    require_usable_directory(flag, parent.string());
  }
  require_writable_directory(flag, parent.string());
  probe();
}

/// The items of one comma-separated argument ("0.1,0.2" -> {"0.1", "0.2"}), empty ones kept.
inline std::vector<std::string> comma_items(const std::string& text) {
  std::vector<std::string> items;
  std::size_t begin = 0;
  for (std::size_t comma; (comma = text.find(',', begin)) != std::string::npos; begin = comma + 1)
    items.push_back(text.substr(begin, comma - begin));
  items.push_back(text.substr(begin));
  return items;
}

/// A list option: comma-separated values (and, as CLI11 lists take them, several arguments or
/// repeats of the flag), each item checked by `item_check`. The one parser of every list of the
/// CLI: an empty item ("0.1,,0.2", a lone ",") is refused as such, where a CLI11 delimiter drops
/// it without a word, or, when nothing is left, takes the next flag as the value. With
/// `empty_is_none`, a list that may be empty (snapshot times), one empty argument given alone
/// (--snapshot-times "") is the empty list: it clears a --config file's values.
template <class T>
CLI::Option* add_list_option(CLI::App* cmd, const std::string& flag, std::vector<T>& target,
                             const std::string& help, CLI::Validator item_check,
                             bool empty_is_none = false) {
  CLI::Validator items(
      [item_check, empty_is_none](std::string& text) -> std::string {
        if (empty_is_none && text.empty()) return {};
        const auto list = comma_items(text);
        std::string checked;  // the items as their check passes them on (integer_in)
        for (std::size_t k = 0; k < list.size(); ++k) {
          if (list[k].empty())
            return fmt::format(
                "empty item {} of {} in the list '{}'; give the values separated "
                "by single commas",
                k + 1, list.size(), text);
          std::string item = list[k];
          if (std::string why = item_check(item); !why.empty()) return why;
          checked += (k == 0 ? "" : ",") + item;
        }
        text = checked;
        return {};
      },
      item_check.get_description(), item_check.get_name());
  return cmd
      ->add_option_function<std::vector<std::string>>(
          flag,
          [&target, flag](const std::vector<std::string>& arguments) {
            target.clear();
            for (const auto& argument : arguments) {
              if (argument.empty()) {  // passed by the check: empty_is_none
                if (arguments.size() > 1)
                  throw UsageError(flag,
                                   "an empty value, which gives no values, among others; "
                                   "give it alone (\"\") for none");
                continue;
              }
              for (const auto& item : comma_items(argument)) {
                T value{};
                if (!CLI::detail::lexical_cast(item, value))  // checked above
                  throw UsageError(flag, "cannot read '" + item + "'");
                target.push_back(value);
              }
            }
          },
          help)
      ->transform(items);
}

/// Throws UsageError(flag, ...) if a value of a list option (state points, N values, modes) is
/// listed twice: its runs would be counted twice, as if independent.
template <class T>
void reject_repeated_values(const std::string& flag, std::vector<T> values,
                            const std::string& remedy) {
  std::sort(values.begin(), values.end());
  const auto repeated = std::adjacent_find(values.begin(), values.end());
  if (repeated != values.end())
    throw UsageError(flag, fmt::format("value {} is listed twice; {}", *repeated, remedy));
}

/// The file a path names, resolved through "..", "." and symbolic links (as far as they exist).
inline std::filesystem::path resolved_path(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path file = fs::weakly_canonical(fs::absolute(path), ec);
  return ec ? fs::absolute(path).lexically_normal() : file;
}

/// Throws UsageError(flag, ...) if two of the (flag, path) outputs name one file (empty paths are
/// skipped): the output written last would replace the other without a word. Likewise if an
/// input the command reads (--config, --restart) is also one of its outputs, which would replace
/// the file it was read from.
inline void require_distinct_files(
    const std::vector<std::pair<std::string, std::string>>& outputs,
    const std::vector<std::pair<std::string, std::string>>& inputs = {}) {
  std::vector<std::pair<std::filesystem::path, std::string>> seen;  // a file and whose it is
  // The output flag that names path's file already, or null.
  const auto owner_of = [&seen](const std::string& path) -> const std::string* {
    const std::filesystem::path file = resolved_path(path);
    for (const auto& [other, owner] : seen)
      if (other == file) return &owner;
    return nullptr;
  };
  for (const auto& [flag, path] : outputs) {
    if (path.empty()) continue;
    if (const std::string* owner = owner_of(path))
      throw UsageError(
          flag, "'" + path + "' is also the file of " + *owner + "; give each output its own file");
    seen.emplace_back(resolved_path(path), flag);
  }
  for (const auto& [flag, path] : inputs)
    if (const std::string* owner = path.empty() ? nullptr : owner_of(path))
      throw UsageError(flag, "'" + path + "' is also the file of " + *owner +
                                 ", which would replace what this command reads; give " + *owner +
                                 " another file");
}

/// Throws UsageError(flag, ...) if the output `path` holds a checkpoint: a stopped run's only way
/// on, which only --checkpoint may replace (by its own rule, require_replaceable_by_checkpoint).
inline void require_no_checkpoint_at(const std::string& flag, const std::string& path) {
  if (sim::is_checkpoint_file(path))
    throw UsageError(flag, path +
                               " holds the checkpoint of a run, which this output would "
                               "replace: choose another name, or remove that file");
}

}  // namespace molchaos::app
