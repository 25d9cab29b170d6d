// --config FILE for every subcommand: a TOML file or a result CSV's header (config_file.hpp).
#include "config_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <ostream>
#include <set>
#include <sstream>
#include <string_view>
#include <variant>

#include "cli_support.hpp"
#include "molchaos/sim/checkpoint.hpp"
#include "molchaos/sim/csv.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/version.hpp"
#include "repeated_options.hpp"
#include "toml_reader.hpp"
#ifdef MOLCHAOS_HAVE_IO
#include "molchaos/io/h5md_parameters.hpp"
#endif

namespace molchaos::app {
namespace {

// Header keys of a run or snapshot CSV that describe the result, not its input.
const std::set<std::string> k_result_keys = {
    "version", "stop_reason", "collisions", "events", "rows", "cache_key", "checksum", "t", "box"};

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() &&
         text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

// What a --config file holds, by its content. An extended XYZ file: a particle count on its first
// line, its comment line with Properties=. A result CSV: "# key = value" lines and then a column
// line, names between commas and no '='; in a TOML file the first line that is no comment is a
// key = value line (or a table, which read_toml refuses). A file of comments alone is a result
// header whose rows were cut off when it names the version that wrote it ("# version = "), and
// TOML otherwise: a TOML file's commented-out keys are no keys.
enum class Kind { toml, csv, xyz };

// The first line of a TOML file of a run's parameters (write_config_toml), which marks it as one.
constexpr std::string_view k_parameters_title = "# molchaos simulate parameters";

Kind kind_of(const std::string& text) {
  std::istringstream in(text);
  std::string first, second;
  std::getline(in, first);
  std::getline(in, second);
  const std::string count = trim(first);
  if (!count.empty() && count.find_first_not_of("0123456789") == std::string::npos &&
      second.find("Properties=") != std::string::npos)
    return Kind::xyz;
  if (!text.starts_with("#")) return Kind::toml;
  in.clear();
  in.seekg(0);
  for (std::string line; std::getline(in, line);) {
    const std::string content = trim(line);
    if (content.empty() || content[0] == '#') continue;
    const bool columns =
        content.find('=') == std::string::npos && content.find(',') != std::string::npos;
    return columns ? Kind::csv : Kind::toml;
  }
  return text.find("\n# version = ") != std::string::npos ? Kind::csv : Kind::toml;
}

// The offset of the first NUL byte or byte that is no part of UTF-8 in `text`, npos where none;
// a character cut at the end of `text` (a prefix of a longer file) counts as text.
std::size_t first_binary_byte(std::string_view text) {
  for (std::size_t at = 0; at < text.size();) {
    const auto byte = static_cast<unsigned char>(text[at]);
    if (byte == 0) return at;
    const std::size_t length = byte < 0x80                   ? 1
                               : byte >= 0xC2 && byte < 0xE0 ? 2
                               : byte >= 0xE0 && byte < 0xF0 ? 3
                               : byte >= 0xF0 && byte < 0xF5 ? 4
                                                             : 0;
    if (length == 0) return at;
    for (std::size_t k = 1; k < length; ++k)
      if (at + k < text.size() && (static_cast<unsigned char>(text[at + k]) & 0xC0) != 0x80)
        return at;
    at += length;
  }
  return std::string::npos;
}

// The words of a value, split at spaces (a list such as snapshot_times "0 1 10").
std::vector<std::string> words(const std::string& value) {
  std::vector<std::string> found;
  std::string word;
  for (std::size_t at = 0; at <= value.size(); ++at) {
    if (at == value.size() || value[at] == ' ') {
      if (!word.empty()) found.push_back(word);
      word.clear();
    } else {
      word += value[at];
    }
  }
  return found;
}

// The word after "molchaos" in a result CSV's title line: "# molchaos sweep summary ..." -> "sweep"
// (a command's name, or another word: "snapshot").
std::string writer_named(const std::string& text) {
  constexpr std::string_view k_prefix = "# molchaos ";
  if (!text.starts_with(k_prefix)) return {};
  const std::size_t end = text.find_first_not_of("abcdefghijklmnopqrstuvwxyz", k_prefix.size());
  return text.substr(k_prefix.size(), end - k_prefix.size());
}

// A checkpoint's head (sim::checkpoint_head): its parameters in the table's order, as a run's CSV
// header names them (its format, version and layout are no parameters).
ConfigItems read_checkpoint_head(const std::string& text, const std::string& path) {
  std::map<std::string, std::string> head;
  try {
    head = sim::checkpoint_head(text, path);
  } catch (const sim::CheckpointError& e) {
    throw UsageError("--config", e.what());
  }
  ConfigItems items;
  for (const sim::ParameterInfo& info : sim::parameter_table())
    if (const auto it = head.find(std::string(info.name)); it != head.end())
      items.emplace_back(it->first, words(it->second));
  return items;
}

// A result CSV: "# key = value" lines up to the column line; lists are space separated. A header
// line without its line end is the end of a file cut short ("# t_end = 20" of "200"): refused.
ConfigItems read_csv_header(std::istream& in, const std::string& path) {
  ConfigItems items;
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') {
    if (in.eof())
      throw UsageError("--config", path + ": ends in the middle of its header line '" + line +
                                       "' (a file cut short?)");
    if (line.back() == '\r') line.pop_back();  // a file saved with Windows line ends
    const auto eq = line.find(" = ");
    if (eq == std::string::npos || line.size() < 2) continue;
    const std::string key = trim(line.substr(1, eq - 1));
    // The title line has words and spaces; a key is one word (a flag's name too, t-end, which
    // --config takes as it takes t_end: skipped, an edited line would be dropped unseen).
    if (key.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") != std::string::npos)
      continue;
    items.emplace_back(key, words(line.substr(eq + 3)));
  }
  return items;
}

// The comment line of an extended XYZ file's first frame: key=value pairs, a value with spaces in
// double quotes. The frame's own keys (box, columns, time, collisions) are no inputs.
ConfigItems read_xyz_header(std::istream& in, const std::string& path) {
  std::string count, comment;
  if (!std::getline(in, count) || !std::getline(in, comment))
    throw UsageError("--config", path + ": no comment line (not an extended XYZ file)");
  if (in.eof())
    throw UsageError("--config",
                     path + ": ends in the middle of its first comment line (a file cut short?)");
  if (!comment.empty() && comment.back() == '\r') comment.pop_back();
  static const std::set<std::string> k_frame_keys = {"Lattice", "Properties", "Time", "Collisions",
                                                     "pbc"};
  ConfigItems items;
  std::size_t at = 0;
  while (at < comment.size()) {
    if (comment[at] == ' ') {
      ++at;
      continue;
    }
    const auto eq = comment.find('=', at);
    if (eq == std::string::npos)
      throw UsageError("--config", path + ": '" + comment.substr(at) +
                                       "' in the first comment line is no key=value pair");
    const std::string key = comment.substr(at, eq - at);
    std::string value;
    if (eq + 1 < comment.size() && comment[eq + 1] == '"') {
      const auto close = comment.find('"', eq + 2);
      if (close == std::string::npos)
        throw UsageError("--config", path + ": unterminated quote after '" + key + "='");
      value = comment.substr(eq + 2, close - eq - 2);
      at = close + 1;
    } else {
      at = std::min(comment.find(' ', eq), comment.size());
      value = comment.substr(eq + 1, at - eq - 1);
    }
    // Extended XYZ's logicals: the writer gives the run's flags as T and F, as ASE reads them.
    if (value == "T" || value == "F") value = value == "T" ? "true" : "false";
    if (k_frame_keys.count(key) == 0) items.emplace_back(key, words(value));
  }
  if (items.empty())
    throw UsageError("--config", path + ": no run parameters in its first comment line");
  return items;
}

// The option of `key` in cmd: the flag of a field name (a parameter table name, a sweep's
// t_end_in_tau0), else --key, else --key with '_' as '-'. nullptr when none.
CLI::Option* option_of(CLI::App* cmd, const std::string& key) {
  if (CLI::Option* op = cmd->get_option_no_throw(flag_of_field(key))) return op;
  if (CLI::Option* op = cmd->get_option_no_throw("--" + key)) return op;
  std::string dashed = key;
  std::replace(dashed.begin(), dashed.end(), '_', '-');
  return cmd->get_option_no_throw("--" + dashed);
}

// True for the options of the parameter table's list rows (snapshot_times), whose empty list is
// their default: no values.
bool takes_empty_list(const CLI::Option* op) {
  for (const sim::ParameterInfo& info : sim::parameter_table())
    if (std::holds_alternative<std::vector<double> sim::Parameters::*>(info.field) &&
        op->check_name(std::string(info.flag)))
      return true;
  return false;
}

std::string allowed_keys(CLI::App* cmd) {
  std::string keys;
  for (const CLI::Option* op : cmd->get_options()) {
    const std::string name = op->get_single_name();
    if (name.empty() || name == "help" || name == "config" || !op->get_configurable()) continue;
    keys += (keys.empty() ? "" : ", ") + name;
  }
  return keys;
}

}  // namespace

ConfigFile read_config_file(const std::string& path) {
  // Read once: a pipe (--config <(...), /dev/stdin) can be read only once, and the kind of file
  // is told by what it holds, whatever its name ends in. At most k_read_limit bytes, far more
  // than any file of options or result header (a result file's rows beyond are not needed), so
  // that an endless input (/dev/zero) is refused instead of filling the memory.
  constexpr std::size_t k_read_limit = std::size_t{16} << 20;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("--config", "cannot read '" + path + "'");
  std::string text;
  char chunk[1 << 16];
  while (text.size() < k_read_limit && in) {
    in.read(chunk, sizeof chunk);
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw UsageError("--config", "cannot read '" + path + "'");
  const bool cut = text.size() >= k_read_limit && in.peek() != std::char_traits<char>::eof();
  static constexpr std::string_view k_hdf5 = "\x89HDF\r\n\x1a\n";
  if (text.starts_with(k_hdf5)) {
#ifdef MOLCHAOS_HAVE_IO
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      throw UsageError("--config", path + ": an HDF5 file is read from a regular file, not a pipe");
    try {
      return {io::read_h5md_parameters(path), true, true, {}, {}};
    } catch (const std::runtime_error& e) {
      throw UsageError("--config", e.what());
    }
#else
    throw UsageError("--config", path + ": an HDF5 file, and this build reads none (no HDF5)");
#endif
  }
  // A UTF-8 byte order mark (as some Windows editors save) is no part of the first key.
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
  // An empty file sets nothing: the defaults would run in place of the run the file was meant
  // to repeat (an extended XYZ file of a run that reached none of its snapshot times is empty).
  if (text.find_first_not_of(" \t\r\n\f\v") == std::string::npos)
    throw UsageError("--config", path + ": empty (no settings to read)");
  std::istringstream lines(text);
  if (text.starts_with(sim::k_checkpoint_magic))
    return {read_checkpoint_head(text, path), true, true, {}, {}};
  // The other kinds are text (TOML is UTF-8, the result files are written so): a NUL byte or a
  // byte that is no UTF-8 in the first 64 KiB marks a binary file, which the TOML reader would
  // refuse as "expected key = value" on its first line, as if a line were mistyped. (An endless
  // input, /dev/zero, is refused below as such.)
  if (const std::size_t at = first_binary_byte(std::string_view(text).substr(0, 1 << 16));
      !cut && at != std::string::npos)
    throw UsageError("--config", path + ": not a text file (byte " + std::to_string(at + 1) +
                                     " is no UTF-8 text): --config reads a TOML file, a result "
                                     "CSV, an extended XYZ file, an H5MD trajectory or a "
                                     "checkpoint");
  switch (kind_of(text)) {
    case Kind::xyz:
      return {read_xyz_header(lines, path), true, true, {}, {}};
    case Kind::csv:
      return {read_csv_header(lines, path),
              true,
              text.starts_with(sim::k_run_title),
              writer_named(text),
              {}};
    case Kind::toml:
      if (ends_with(path, ".csv") && !text.starts_with("#"))
        throw UsageError("--config",
                         path + ": no '# key = value' header (not a molchaos result file)");
      if (cut)
        throw UsageError("--config", path +
                                         ": longer than 16 MiB and not a result file; a file "
                                         "of options is a few lines of key = value");
      {
        std::map<std::string, std::string> quoted_literals;
        ConfigItems items = read_toml(lines, path, quoted_literals);
        // Comments alone set nothing either: the defaults would run in place of the meant run.
        if (items.empty()) throw UsageError("--config", path + ": no settings (comments only)");
        // A run's parameters as --write-config wrote them are a run's file like its CSV: another
        // command takes the state point from it and names what it has no option for.
        const bool run_parameters = text.starts_with(k_parameters_title);
        return {std::move(items), run_parameters, run_parameters, {}, std::move(quoted_literals)};
      }
  }
  return {};
}

void add_config_option(CLI::App* cmd, std::string& path) {
  cmd->add_option("--config", path,
                  "Options from a TOML file (key = value, keys as the flags or the parameter "
                  "names), a result CSV's header, an H5MD trajectory's /parameters or an "
                  "extended XYZ file's first comment line (repeats that run); flags given win")
      ->check(CLI::ExistingFile)
      ->configurable(false);
}

namespace {
// What a --config file (or a --restart checkpoint, read the same way) gave an option, by (file,
// option's long name): the values it wrote, and whether they are the option's, which they are
// not where a flag on the command line, or a file read before, had given it one. One record
// answers both who set an option and what a file wrote for it.
struct FileValues {
  std::vector<std::string> values;
  bool set = false;
};

std::map<std::pair<std::string, std::string>, FileValues>& values_in_files() {
  static std::map<std::pair<std::string, std::string>, FileValues> values;
  return values;
}
}  // namespace

std::string config_file_that_set(const std::string& flag) {
  for (const auto& [key, file] : values_in_files())
    if (key.second == flag && file.set) return key.first;
  return {};
}

std::vector<std::string> config_file_values(const std::string& path, const std::string& flag) {
  const auto it = values_in_files().find({path, flag});
  return it == values_in_files().end() ? std::vector<std::string>() : it->second.values;
}

void require_config_table_kept(const CLI::App& cmd, const std::string& config,
                               const std::string& out_directory) {
  if (config.empty() || resolved_path(config).parent_path() !=
                            resolved_path(out_directory.empty() ? "." : out_directory))
    return;
  std::string changed;
  for (const auto& [key, file] : values_in_files()) {
    if (key.first != config || file.set) continue;  // the file's value stands
    const CLI::Option* op = cmd.get_option_no_throw(key.second);
    if (op == nullptr || op->results() == file.values) continue;
    changed += fmt::format("{}{} {} where the table has {}", changed.empty() ? "" : ", ",
                           key.second, fmt::join(op->results(), ","), fmt::join(file.values, ","));
  }
  if (!changed.empty())
    throw UsageError("--out", "'" + out_directory + "' holds " + config +
                                  ", the table --config read, which this " + cmd.get_name() +
                                  " would replace with another run's (" + changed +
                                  "): give another --out, or copy the table elsewhere first");
}

bool take_default_over_forced_relaxation(double& relax, const CLI::Option& option,
                                         const std::string& config, bool runs_relax,
                                         const std::string& relaxing_runs) {
  if (config.empty() || !runs_relax || relax != 0 ||
      config_file_that_set(option.get_name()) != config)
    return false;
  const sim::ParameterInfo& method = *sim::find_parameter("method");
  const std::vector<std::string> written = config_file_values(config, std::string(method.flag));
  if (written.size() != 1) return false;
  sim::Parameters of_file;
  try {
    sim::parse_value(of_file, method, written[0]);
  } catch (const std::invalid_argument&) {  // checked when the file was read
    return false;
  }
  if (sim::method_relaxes(of_file.method)) return false;
  const sim::Parameters defaults;
  relax = defaults.relax_collisions_per_particle;
  std::cerr << "note: --config " << config << ": relax_collisions_per_particle = 0 was "
            << upper_case(sim::format_value(of_file, method)) << "'s (it does not relax); "
            << relaxing_runs << " "
            << sim::format_value(defaults, *sim::find_parameter("relax_collisions_per_particle"))
            << " collisions per particle, the default (--relax 0 for none)\n";
  return true;
}

std::string upper_case(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

namespace {
// Refuses a run's header that lacks a parameter of the table (beyond those left out at their
// default): the file was cut short, and the missing values would run as defaults.
void check_run_header_complete(const ConfigItems& items, const std::string& path) {
  std::string missing;
  for (const sim::ParameterInfo& info : sim::parameter_table()) {
    if (info.omitted_at_default) continue;
    const bool named = std::any_of(items.begin(), items.end(),
                                   [&](const auto& item) { return item.first == info.name; });
    if (!named) missing += (missing.empty() ? "" : ", ") + std::string(info.name);
  }
  if (!missing.empty())
    throw UsageError("--config", path + ": the run's header lacks " + missing +
                                     " (a file cut short?); a run's header names every parameter");
}
}  // namespace

namespace {
// A result file's parameters that name no option of cmd are not used by it. The TC model's
// duration, which changes the gas, is refused where set (cmd would treat another gas); the others
// are returned, "name = value, ...", for the note that names them once the file is applied (the
// run's seed, length and stopping rules, which cmd chooses in its own way, or its gas where cmd
// runs one of its own).
std::string parameters_not_taken(CLI::App* cmd, const ConfigItems& items, const std::string& path) {
  std::string dropped;
  for (const auto& [key, values] : items) {
    const sim::ParameterInfo* info = sim::find_parameter(key);
    if (info == nullptr || option_of(cmd, key) != nullptr) continue;
    std::string text;
    for (const auto& v : values) text += (text.empty() ? "" : " ") + v;
    if (info->name == "tc") {
      sim::Parameters file;
      try {
        sim::parse_value(file, *info, text);
        sim::check_range(file, *info);
      } catch (const std::invalid_argument& e) {
        throw UsageError("--config", path + ": " + e.what());
      }
      if (file.tc > 0.0)
        throw UsageError("--config", path + ": the run uses the TC model (tc = " + text +
                                         "), and " + cmd->get_name() +
                                         " has no option for it: it would treat another gas");
    }
    dropped += (dropped.empty() ? "" : ", ") + key + " = " + (text.empty() ? "none" : text);
  }
  return dropped;
}
}  // namespace

void apply_config_file(CLI::App* cmd, const std::string& path) {
  if (path.empty()) return;
  const auto [items, result_file, run_header, writer, quoted_literals] = read_config_file(path);
  if (run_header) check_run_header_complete(items, path);
  // A table of another command (a sweep summary given to theory): its keys are that command's
  // options, which would be refused one by one as unknown, as if the file were damaged.
  const CLI::App* program = cmd->get_parent();
  const bool other_command =
      program != nullptr && !writer.empty() && writer != cmd->get_name() &&
      !program->get_subcommands([&](const CLI::App* c) { return c->get_name() == writer; }).empty();
  if (result_file && !run_header && other_command)
    throw UsageError("--config", path + ": a table of molchaos " + writer + ", which " +
                                     cmd->get_name() + " does not read; `molchaos " + writer +
                                     " --config " + path + "` repeats it");
  // The tables of reproduce describe the study beyond its options: all of it follows from the
  // three they name, quick and seeds, which are required, and base_seed (1 where a table of an
  // earlier version does not name it).
  const bool study_table = result_file && cmd->get_name() == "reproduce";
  for (const char* key : {"quick", "seeds"})
    if (study_table && std::none_of(items.begin(), items.end(),
                                    [&](const auto& item) { return item.first == key; }))
      throw UsageError("--config", path + ": names no " + key +
                                       " (not a table of molchaos reproduce of this version, "
                                       "whose tables name quick and seeds)");
  const std::string not_taken =
      result_file && !study_table ? parameters_not_taken(cmd, items, path) : std::string();
  // The key that set each option: a second key for the same option (repeated, or spelled both
  // as the parameter name and as the flag) would otherwise be dropped without a word.
  std::map<const CLI::Option*, std::string> set_by;
  for (const auto& [key, values] : items) {
    CLI::Option* op = option_of(cmd, key);
    if (op == nullptr || !op->get_configurable()) {
      // A result file names its outputs and the run's other inputs: skipped where not options.
      if (study_table ||
          (result_file && (k_result_keys.count(key) > 0 || sim::find_parameter(key) != nullptr)))
        continue;
      throw UsageError("--config", path + ": unknown key '" + key + "' for " + cmd->get_name() +
                                       "; allowed: " + allowed_keys(cmd));
    }
    if (const auto first = set_by.find(op); first != set_by.end())
      throw UsageError("--config", path + ": key '" + key + "' sets " + op->get_name() +
                                       " again (first as '" + first->second +
                                       "'); give each option once");
    set_by.emplace(op, key);
    const bool is_flag = op->get_expected_min() == 0;  // takes true or false
    // TOML types its values: "100" and "true" are strings, which an option that takes numbers
    // or a flag would read as the number or the boolean without a word where the file's writer
    // may have meant another type.
    if (const auto quoted = quoted_literals.find(key); quoted != quoted_literals.end()) {
      bool takes_numbers = true;
      try {
        op->get_validator(k_number_check);
      } catch (const CLI::OptionNotFound&) {
        takes_numbers = false;
      }
      if (takes_numbers || is_flag) {
        std::string bare;
        for (const std::string& v : values) bare += (bare.empty() ? "" : ", ") + v;
        throw UsageError("--config", quoted->second + ": key '" + key + "': " + op->get_name() +
                                         (is_flag ? " takes true or false" : " takes a number") +
                                         ", and the value is a string in quotes; write it bare (" +
                                         key + " = " +
                                         (values.size() == 1 ? bare : "[" + bare + "]") + ")");
      }
    }
    FileValues& record = values_in_files()[{path, op->get_name()}];
    record.values = values;
    if (values.empty()) {
      // An empty list leaves the option at its default: right for a list whose default is no
      // values (snapshot_times, which --write-config writes as [] and the CSV header as nothing
      // after its '='); for any other option it would drop the key without a word.
      if (takes_empty_list(op)) continue;
      throw UsageError("--config",
                       path + ": key '" + key + "': " + op->get_name() +
                           ": an empty value or list; give " +
                           (op->get_items_expected_max() > 1 ? "at least one value" : "one value"));
    }
    if (takes_one_value(*op) && values.size() > 1)
      throw UsageError("--config", path + ": key '" + key + "': " + op->get_name() +
                                       ": takes one value, the file gives " +
                                       std::to_string(values.size()) + "; give one");
    // A flag given on the command line wins, but the file's value is checked all the same (set,
    // then the flag's value set again): a bad file is refused whichever flags come with it.
    const CLI::results_t given = op->results();
    op->clear();
    try {
      if (is_flag) {
        if (values.size() != 1 || (values[0] != "true" && values[0] != "false"))
          throw CLI::ValidationError(op->get_name(), "expects true or false");
        op->add_result(op->get_flag_value(op->get_single_name(), values[0]));
      } else {
        op->add_result(values);
      }
      op->run_callback();
    } catch (const CLI::ParseError& e) {
      throw UsageError("--config", path + ": key '" + key + "': " + e.what());
    }
    if (!given.empty()) {
      op->clear();
      op->add_result(given);
      op->run_callback();
    } else {
      record.set = true;
    }
  }
  // A result file of another command (a run's CSV given to bench) would run the defaults.
  if (result_file && set_by.empty())
    throw UsageError("--config", path + ": sets no option of " + cmd->get_name() +
                                     " (a result file of another command?)");
  if (!not_taken.empty())
    std::cerr << "note: --config " << path << ": " << cmd->get_name()
              << " has no option for the run's " << not_taken << "; not used\n";
  // Another version may compute the same parameters into other bytes (event order, estimators,
  // defaults of options the file does not name): said, so that a difference is not a surprise.
  for (const auto& [key, values] : items)
    if (result_file && key == "version" && values.size() == 1 && values[0] != k_version)
      std::cerr << "note: --config " << path << " was written by molchaos " << values[0]
                << "; this is molchaos " << k_version
                << ": the same parameters need not give the same numbers\n";
}

void write_config_toml(const sim::Parameters& p, std::ostream& out) {
  out << k_parameters_title << " (read back with --config)\n";
  // Read back, it is a result file's key (not an option): --config notes another version.
  out << "version = \"" << k_version << "\"\n";
  for (const sim::ParameterInfo& info : sim::parameter_table()) {
    const std::string text = sim::format_value(p, info);
    out << info.name << " = ";
    if (std::holds_alternative<std::vector<double> sim::Parameters::*>(info.field)) {
      std::string list = text;
      std::replace(list.begin(), list.end(), ' ', ',');
      out << "[" << list << "]\n";
      continue;
    }
    double number = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
    // A seed beyond TOML's integers is written in quotes (read back as the number).
    const bool bare =
        text == "true" || text == "false" ||
        (ec == std::errc() && end == text.data() + text.size() && !beyond_toml_integers(text));
    out << (bare ? text : "\"" + text + "\"") << "\n";
  }
}

}  // namespace molchaos::app
