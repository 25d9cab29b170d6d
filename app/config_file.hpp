// Input files: every subcommand takes its options from a file (--config FILE) as well as from
// flags, the flags winning. A file is either TOML (key = value; strings, booleans, numbers,
// one-line arrays; no tables), a result CSV, whose "# key = value" header is read, an H5MD
// trajectory, whose /parameters attributes are read, an extended XYZ file, whose first
// comment line is read, or a checkpoint, whose head is read (each known by its content, whatever
// its name):
// `simulate --config run.csv` (or run.h5, run.xyz) repeats that run. A key is a
// parameter table name (t_end, relax_collisions_per_particle) or an option's long name (t-end,
// relax, seeds); each value goes through the option's own check, so an out-of-range value names
// its range as a flag would.
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "molchaos/sim/parameters.hpp"

namespace molchaos::app {

/// (key, values) in file order; TOML arrays and the CSV header's space-separated lists give
/// several values, an empty value none.
using ConfigItems = std::vector<std::pair<std::string, std::vector<std::string>>>;

/// A --config file's items, and whether it is a result file (whose keys that name no option of
/// the command, such as its outputs, are skipped).
struct ConfigFile {
  ConfigItems items;
  bool result_file = false;
  /// A header of one simulate run (its CSV, XYZ or H5MD outputs), which names every parameter
  /// of the table: one that lacks any was cut short, and is refused.
  bool run_header = false;
  /// The command that wrote a result CSV, from its title line ("# molchaos sweep summary ..."):
  /// empty where the file names none.
  std::string writer;
  /// A TOML file's keys whose value is a string that reads as a number ("100") or a boolean
  /// ("true"), with the place of each ("path line N"): refused for an option that takes numbers
  /// or a flag.
  std::map<std::string, std::string> quoted_literals;
};

/// Reads a TOML file, a result CSV's header, an H5MD trajectory's parameters, an extended XYZ
/// file's first comment line or a checkpoint's head, told apart by their content; throws
/// UsageError("--config", ...) naming the file and line of a syntax error.
ConfigFile read_config_file(const std::string& path);

/// Adds --config FILE to cmd; `path` receives it. Call apply_config_file() first thing in cmd's
/// callback (after the command line is parsed, so flags given there win).
void add_config_option(CLI::App* cmd, std::string& path);

/// Gives every option of cmd not set on the command line its value from the file (if any);
/// throws UsageError naming the file and the key: unknown key (with the allowed keys), or the
/// option's check failing (with its allowed range).
void apply_config_file(CLI::App* cmd, const std::string& path);

/// The --config file that gave the option `flag` (its long name, "--relax") its value, where no
/// flag on the command line gave one; empty otherwise. main() names it beside a refusal of that
/// value, which the user may not have typed (a result file's relaxation, read for another method).
std::string config_file_that_set(const std::string& flag);

/// The values the --config file `path` gave the option `flag` (its long name, "--method"), read
/// whether or not a flag on the command line overrode them; empty where the file names none.
std::vector<std::string> config_file_values(const std::string& path, const std::string& flag);

/// A relaxation of 0 that the --config file `config` gave (`option`, no flag overriding it) and a
/// run of a method that does not relax wrote (a DSMC result's header, whose 0 that method forced),
/// read by a command whose runs relax (`runs_relax`: `--config dsmc.csv --method edmd`): that 0
/// is no choice of the user's, and would start EDMD from its lattice, unrelaxed, without a word.
/// Sets `relax` to the default instead and notes it on stderr ("...; <relaxing_runs> 20
/// collisions per particle, the default (--relax 0 for none)"); returns whether it did. Kept as
/// given: a flag (--relax 0 included), a file whose method relaxes, a value other than 0.
bool take_default_over_forced_relaxation(double& relax, const CLI::Option& option,
                                         const std::string& config, bool runs_relax,
                                         const std::string& relaxing_runs);

/// Throws UsageError("--out", ...) if the --config file `config` lies in the output folder
/// `out_directory` of a command that writes its tables there (reproduce, bench) and a flag on the
/// command line changed a value the file gave: the run would replace the table it was read from
/// with another run's. Re-running the table as it is (the same values) rewrites it in place.
void require_config_table_kept(const CLI::App& cmd, const std::string& config,
                               const std::string& out_directory);

/// The text in capitals ("edmd" -> "EDMD"), as the notes name a method.
std::string upper_case(std::string text);

/// cmd's callback: reads --config FILE (added here) into the options not given as flags, then
/// runs `action`, given the file's path (empty: none) where it takes one, so that a command
/// can keep its outputs off the file it read.
template <class Action>
void set_callback_with_config(CLI::App* cmd, Action action) {
  auto path = std::make_shared<std::string>();
  add_config_option(cmd, *path);
  cmd->callback([cmd, path, action] {
    apply_config_file(cmd, *path);
    if constexpr (std::is_invocable_v<Action, const std::string&>)
      action(*path);
    else
      action();
  });
}

/// The parameters as a TOML file that --config reads back (parameter table names as keys).
void write_config_toml(const sim::Parameters& p, std::ostream& out);

}  // namespace molchaos::app
