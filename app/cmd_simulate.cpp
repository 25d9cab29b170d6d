// `molchaos simulate`: flags -> sim::Parameters (validated once), run, write the CSV atomically.
// No physics here.
#include <signal.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli_support.hpp"
#include "commands.hpp"
#include "config_file.hpp"
#include "interrupt_signals.hpp"
#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/sim/sim.hpp"
#include "molchaos/validation/run_pair_correlations.hpp"
#ifdef MOLCHAOS_HAVE_IO
#include "molchaos/io/h5md_writer.hpp"
#include "molchaos/io/xyz_writer.hpp"
#endif
#include "parameter_options.hpp"

namespace molchaos::app {
namespace {

struct SimulateOptions {
  sim::Parameters parameters;
  std::string out = "run.csv";
  std::string trajectory;         // H5MD file of the snapshots (empty: none)
  std::string xyz;                // extended XYZ file of the snapshots (empty: none)
  std::string pair_correlations;  // g(r), G_par(r), G_perp(r) of the snapshots (empty: none)
  bool quiet = false;
  std::string write_config;  // TOML file of the parameters (empty: none)
  sim::CheckpointOptions checkpoints;
  std::string config;  // the --config file read (empty: none), which no output may replace

  /// Every file the run writes (empty names: not asked for): its outputs and its checkpoint.
  std::vector<std::string> written_files() const {
    return {out, write_config, pair_correlations, trajectory, xyz, checkpoints.path};
  }
};

// The run, or nothing when a signal interrupted it (the checkpoint is then written).
std::optional<sim::RunResult> run_checkpointed(const SimulateOptions& options,
                                               const sim::ProgressReporter& progress,
                                               sim::CheckpointRecord& record) {
  sim::CheckpointOptions checkpoints = options.checkpoints;
  checkpoints.record = &record;
  // A periodic checkpoint that cannot be written (a full disk, a folder gone) costs only the
  // safety net, not the run: its result does not depend on it. The run goes on, warned at once
  // (on a line of its own below the progress display, if shown), and the file keeps the last
  // checkpoint written, whole.
  checkpoints.write_failed = [&path = options.checkpoints.path, shown = bool(progress)](
                                 double time, const std::string& reason) {
    std::fprintf(stderr,
                 "%swarning: --checkpoint: the checkpoint at t = %s could not be written (%s); "
                 "the run goes on, and %s keeps the last checkpoint written, if any (free space "
                 "or fix the folder for the next one)\n",
                 shown ? "\n" : "", sim::message_number(time).c_str(), reason.c_str(),
                 path.c_str());
  };
  // SIGTERM (a batch system's wall-time limit) and SIGINT: during the run, with a checkpoint
  // file, they ask for a checkpoint and an end (the run marks itself under way once the
  // relaxation, which has no checkpoint, is done); without one, and during the relaxation, they
  // end the process at once, with nothing written. While the outputs are written they wait.
  interrupt_signals::install();
  if (!checkpoints.path.empty()) {
    checkpoints.interrupt = &interrupt_signals::requested();
    checkpoints.under_way = &interrupt_signals::under_way();
  }
  try {
    return sim::run_with_checkpoints(options.parameters, progress, checkpoints);
  } catch (const sim::CheckpointError& e) {
    throw UsageError("--restart", e.what());
  } catch (const std::invalid_argument& e) {  // refused by the engine (too long a relaxation)
    throw_as_usage_error("simulate", e.what());
  } catch (const std::exception& e) {
    // The checkpoint a signal asked for could not be written (a full disk): the run is lost, and
    // the message says which signal ended it, beside why nothing was saved.
    if (!interrupt_signals::requested().load()) throw;
    throw std::runtime_error("stopped by " + std::string(interrupt_signals::signal_name()) +
                             ", but its checkpoint could not be written (" + e.what() +
                             "): the run since the last checkpoint is lost");
  }
}

// "dir/run.csv" -> "dir/run.snapshot<k>.csv": the extension of the file name only (a dot in a
// directory name such as data.v2/ or ../ is not an extension).
std::string snapshot_path(const std::string& out, std::size_t index) {
  const std::filesystem::path p(out);
  std::string stem = p.filename().string();
  const auto dot = stem.rfind('.');
  if (dot != std::string::npos && dot != 0) stem.resize(dot);
  return (p.parent_path() / (stem + ".snapshot" + std::to_string(index) + ".csv")).string();
}

// The run parameters a result file's header holds ("# key = value" lines of parameters, and the
// version line), as written; empty when the file cannot be read or names none.
std::vector<std::string> parameter_lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line) && line.starts_with("# ");) {
    const auto equals = line.find(" = ");
    if (equals == std::string::npos) continue;
    const std::string key = line.substr(2, equals - 2);
    if (key == "version" || sim::find_parameter(key) != nullptr) lines.push_back(line);
  }
  return lines;
}

// The snapshot files of the run whose CSV this run replaced (`replaced`: its parameter lines,
// empty if there was none), numbered from `from` on: the run that wrote them is gone, and they
// would pass for this run's. Only files written by that run (the same parameter lines) are
// removed, and none of this run's own files: another run's files (an --out differing only in
// its extension names the same snapshots), the files this run wrote and the files it read (its
// --config, which may be such a snapshot, and its --restart) stay.
void remove_earlier_snapshots(const SimulateOptions& o, std::size_t from,
                              const std::vector<std::string>& replaced) {
  if (replaced.empty()) return;
  std::vector<std::string> own_files = o.written_files();
  own_files.push_back(o.checkpoints.restart);
  own_files.push_back(o.config);
  const auto own = [&own_files](const std::string& path) {
    std::error_code ec;
    for (const std::string& f : own_files)
      if (!f.empty() && std::filesystem::equivalent(path, f, ec)) return true;
    return false;
  };
  // The replaced run's snapshot times name how many files it wrote: each is visited, so a gap
  // (one of them removed by hand) leaves none of the later ones behind.
  std::size_t count = 0;
  for (const std::string& line : replaced)
    if (line.starts_with("# snapshot_times = ")) {
      std::istringstream times(line.substr(std::string_view("# snapshot_times = ").size()));
      for (std::string time; times >> time;) count += time != "none";
    }
  std::error_code ignored;
  for (std::size_t k = from; k < count; ++k) {
    const std::string path = snapshot_path(o.out, k);
    if (!own(path) && parameter_lines(path) == replaced) std::filesystem::remove(path, ignored);
  }
}

// Every output of the run, written as one (sim::StagedFiles): all files or none, and a full disk
// leaves the files of a run before in place. Written with the results, so that a run refused on
// the way (a checkpoint of other parameters) or interrupted leaves no file. SIGINT and SIGTERM
// are recorded while the files are written (a signal's default end would leave temporaries
// behind), and run_simulate ends by them once the files are in place; temporaries of a writer
// killed outright are removed by the next run (their age rule in sim::remove_stale_temporaries).
// Snapshot files beyond the run's own that the run it replaces wrote (of times this one did not
// reach, or more snapshot times) are removed (remove_earlier_snapshots).
void write_outputs(const SimulateOptions& options, const sim::RunResult& result) {
  const sim::Parameters& p = options.parameters;
  interrupt_signals::under_way().store(true);
  for (const std::string& path : options.written_files())
    if (!path.empty()) {
      const std::string directory = std::filesystem::path(path).parent_path().string();
      sim::remove_stale_temporaries(directory.empty() ? "." : directory);
    }
  sim::StagedFiles files;
  if (!options.write_config.empty())
    files.write(options.write_config, [&](std::ostream& out) { write_config_toml(p, out); });
  files.write(options.out, [&](std::ostream& out) { sim::write_csv(result, out); });
  for (std::size_t k = 0; k < result.snapshots.size(); ++k)
    files.write(snapshot_path(options.out, k),
                [&](std::ostream& out) { sim::write_snapshot_csv(result, k, out); });
  if (!options.pair_correlations.empty())
    files.write(options.pair_correlations,
                [&](std::ostream& out) { validation::write_run_pair_correlations(result, out); });
#ifdef MOLCHAOS_HAVE_IO
  if (!options.trajectory.empty()) io::write_h5md_file(result, options.trajectory, files);
  // An XYZ file is its frames, and the run's parameters ride on their comment lines: a run that
  // stopped before its first snapshot time has none, and an empty file could not be re-run.
  const bool xyz_frames = !options.xyz.empty() && !result.snapshots.empty();
  if (xyz_frames) io::write_xyz_file(result, options.xyz, files);
#endif
  const std::vector<std::string> replaced = parameter_lines(options.out);  // before the commit
  files.commit();
  remove_earlier_snapshots(options, result.snapshots.size(), replaced);
#ifdef MOLCHAOS_HAVE_IO
  if (!options.xyz.empty() && !xyz_frames) {
    // The file of that name is an earlier run's (its frames are not this run's): removed, as a
    // rename of this run's file would have replaced it.
    std::error_code ignored;
    const bool removed = std::filesystem::remove(options.xyz, ignored);
    std::fprintf(stderr,
                 "note: no snapshot time reached before the run stopped: no --xyz file written "
                 "(an XYZ file holds frames only)%s; %s repeats the run\n",
                 removed ? (", the earlier " + options.xyz + " removed").c_str() : "",
                 options.out.c_str());
  }
#endif
}

void run_simulate(const SimulateOptions& options) {
  const sim::Parameters& p = options.parameters;
  // First, before the outputs' folders and names are looked at: DSMC keeps velocities only, so
  // it has no configurations to write, and no checkpoints.
  if (p.method == sim::Method::dsmc) {
    for (const auto& [flag, path] :
         {std::pair{"--trajectory", &options.trajectory}, std::pair{"--xyz", &options.xyz},
          std::pair{"--pair-correlations", &options.pair_correlations}})
      if (!path->empty())
        throw UsageError(flag,
                         "not allowed with --method dsmc (it has no positions); allowed "
                         "with --method edmd");
    for (const auto& [flag, path] : {std::pair{"--checkpoint", &options.checkpoints.path},
                                     std::pair{"--restart", &options.checkpoints.restart}})
      if (!path->empty())
        throw UsageError(flag,
                         "not allowed with --method dsmc (it has no checkpoints); allowed "
                         "with --method edmd");
  }
  require_writable_file("--out", options.out, /*create_parent=*/false);
  for (std::size_t k = 0; k < p.snapshot_times.size(); ++k)
    require_writable_file("--out", snapshot_path(options.out, k), /*create_parent=*/false);
  if (!options.trajectory.empty()) require_writable_file("--trajectory", options.trajectory, false);
  if (!options.xyz.empty()) require_writable_file("--xyz", options.xyz, false);
  if (!options.pair_correlations.empty())
    require_writable_file("--pair-correlations", options.pair_correlations, false);
  const sim::CheckpointOptions& checkpoints = options.checkpoints;
  if (!checkpoints.path.empty()) require_writable_file("--checkpoint", checkpoints.path, false);
  {
    // Every file the run writes, the file its options came from, and the checkpoint it
    // continues (which only --checkpoint may replace: the usual way to go on from where a run
    // stopped).
    std::vector<std::pair<std::string, std::string>> files{{"--out", options.out}};
    for (std::size_t k = 0; k < p.snapshot_times.size(); ++k)
      files.emplace_back("--out (its snapshot " + std::to_string(k) + ")",
                         snapshot_path(options.out, k));
    files.insert(files.end(), {{"--trajectory", options.trajectory},
                               {"--xyz", options.xyz},
                               {"--pair-correlations", options.pair_correlations},
                               {"--write-config", options.write_config},
                               {"--checkpoint", checkpoints.path}});
    require_distinct_files(files, {{"--config", options.config}});
    files.pop_back();
    require_distinct_files(files, {{"--restart", checkpoints.restart}});
    for (const auto& [flag, path] : files) require_no_checkpoint_at(flag, path);
  }
  {
    // A snapshot file this run would write that another run wrote (a snapshot, or another of its
    // tables given that name; its parameter lines are not those of the CSV this run replaces: an
    // --out differing only in its extension, run.txt beside run.csv, names the same snapshots)
    // would be overwritten, and that run's set mixed.
    const std::vector<std::string> replaced = parameter_lines(options.out);
    for (std::size_t k = 0; k < p.snapshot_times.size(); ++k) {
      const std::string path = snapshot_path(options.out, k);
      const std::vector<std::string> lines = parameter_lines(path);
      if (!lines.empty() && lines != replaced)
        throw UsageError("--out", path + " holds results of another run (not of the run in " +
                                      options.out +
                                      "), which this run would overwrite: choose "
                                      "another --out, or remove that file");
      // A file of the user's own at a name the run derives (no result file of this suite: no
      // parameter lines) would be replaced without a word.
      std::error_code ec;
      if (lines.empty() && std::filesystem::is_regular_file(path, ec) &&
          std::filesystem::file_size(path, ec) > 0)
        throw UsageError("--out", path + ", the name of this run's snapshot " + std::to_string(k) +
                                      ", holds a file that is no result of molchaos, which this "
                                      "run would overwrite: choose another --out, or remove "
                                      "that file");
    }
  }
  try {
    sim::require_replaceable_by_checkpoint(checkpoints.path, checkpoints.restart);
  } catch (const std::invalid_argument& e) {
    throw UsageError("--checkpoint", e.what());
  }
  if (checkpoints.path.empty() && (checkpoints.interval > 0 || checkpoints.wall_interval > 0))
    throw UsageError(checkpoints.interval > 0 ? "--checkpoint-interval" : "--checkpoint-wall",
                     "needs --checkpoint FILE");
  if (!checkpoints.restart.empty()) {
    // A path that exists but holds no checkpoint (/dev/null, a directory, an empty file) is
    // named as what it is: "no checkpoint file" reads as a mistyped name.
    namespace fs = std::filesystem;
    std::error_code ec;
    const std::string& restart = checkpoints.restart;
    if (!fs::exists(restart, ec))
      throw UsageError("--restart", "no checkpoint file '" + restart + "'");
    if (!fs::is_regular_file(restart, ec))
      throw UsageError("--restart", "'" + restart +
                                        "' is not a regular file (a checkpoint is one, as "
                                        "--checkpoint FILE wrote it)");
    if (fs::file_size(restart, ec) == 0)
      throw UsageError("--restart", "'" + restart + "' is empty (no checkpoint in it)");
  }
  // A restart keeps the run's snapshot times (only t_end may change): a new t_end before the last
  // of them is refused as such, not as a snapshot time out of range.
  if (const auto last = std::max_element(p.snapshot_times.begin(), p.snapshot_times.end());
      !checkpoints.restart.empty() && last != p.snapshot_times.end() && p.t_end < *last &&
      config_file_that_set("--snapshot-times") == checkpoints.restart)
    throw UsageError("--t-end",
                     fmt::format("value {} lies before {}, the last snapshot time of the "
                                 "run in {}, which a restart keeps; allowed: t_end >= {} "
                                 "(and after the checkpoint's time)",
                                 p.t_end, *last, checkpoints.restart, *last));
  try {
    sim::validate(p);
  } catch (const std::invalid_argument& e) {
    throw_as_usage_error("simulate", e.what());  // validate() names fields; the user typed flags
  }
  // Configurations are written at --snapshot-times only: without them there is nothing to write
  // (and HDF5 refuses the empty list), found only after the whole run.
  for (const auto& [flag, path] :
       {std::pair{"--trajectory", &options.trajectory}, std::pair{"--xyz", &options.xyz}})
    if (!path->empty() && p.snapshot_times.empty())
      throw UsageError(flag, "needs --snapshot-times (the times of the configurations to write)");
  if (!options.pair_correlations.empty() && p.snapshot_times.empty())
    throw UsageError("--pair-correlations", "needs --snapshot-times (the times to measure at)");

  if (!options.write_config.empty())
    require_writable_file("--write-config", options.write_config, false);

  const bool show_progress = !options.quiet && ::isatty(::fileno(stderr)) != 0;
  sim::ProgressReporter progress;
  if (show_progress)
    progress = [](const sim::Progress& report) {
      const double rate = report.wall_seconds > 0
                              ? static_cast<double>(report.collisions) / report.wall_seconds
                              : 0.0;
      if (report.relaxing)
        std::fprintf(stderr, "\rsimulate: relaxing  %.3g collisions  %.3g M collisions/s   ",
                     static_cast<double>(report.collisions), rate / 1e6);
      else
        std::fprintf(stderr, "\rsimulate: %5.1f%%  %.3g collisions  %.3g M collisions/s   ",
                     100.0 * std::min(1.0, report.fraction_done),
                     static_cast<double>(report.collisions), rate / 1e6);
      std::fflush(stderr);
    };
  sim::CheckpointRecord record;
  const std::optional<sim::RunResult> run = run_checkpointed(options, progress, record);
  if (show_progress) std::fprintf(stderr, "\n");
  if (!run)
    throw Interrupted("simulate: stopped by signal " +
                      std::to_string(interrupt_signals::signal_number()) +
                      "; checkpoint written to " + checkpoints.path + "; continue with --restart " +
                      checkpoints.path);
  const sim::RunResult& result = *run;

  write_outputs(options, result);
  std::fprintf(stderr, "simulate: %llu collisions in %.2f s, stop: %s, wrote %s\n",
               static_cast<unsigned long long>(result.collisions), result.wall_seconds,
               sim::stop_message(result).c_str(), options.out.c_str());
  if (interrupt_signals::requested().load()) {  // came while the outputs were written
    std::fprintf(stderr, "simulate: stopped by %s once its outputs were complete\n",
                 interrupt_signals::signal_name());
    interrupt_signals::end_by_signal();
  }
  // --checkpoint alone writes only on a signal: a run that finished leaves no file to go on from.
  if (checkpoints.only_on_interrupt())
    std::fprintf(stderr,
                 "note: no checkpoint written to %s: without --checkpoint-interval or "
                 "--checkpoint-wall one is written only on SIGINT or SIGTERM\n",
                 checkpoints.path.c_str());
  // An interval the run never reached writes no checkpoint either (the wall clock none as well).
  if (checkpoints.interval > 0 && record.due == 0) {
    const std::string range =
        record.longest_interval > 0
            ? "one is taken with --checkpoint-interval in (0, " +
                  sim::message_number(record.longest_interval) + "]"
            : "the run reached no sample time before its end at which to take one";
    const double end = result.samples.empty() ? record.start : result.samples.back().t;
    std::fprintf(stderr,
                 "note: no checkpoint written to %s: --checkpoint-interval %s is longer than the "
                 "run (t = %s to %s), so no periodic checkpoint was due; %s\n",
                 checkpoints.path.c_str(), sim::message_number(checkpoints.interval).c_str(),
                 sim::message_number(record.start).c_str(), sim::message_number(end).c_str(),
                 range.c_str());
  }
  // A run that stopped early (a stop condition, a collapse) wrote fewer configurations than asked
  // for: the files say so in their rows (no frame in the H5MD file and no --xyz file, a
  // --pair-correlations table without rows), and this line at once.
  if (result.snapshots.size() < p.snapshot_times.size())
    std::fprintf(stderr, "note: %zu of the %zu snapshot times reached before the run stopped\n",
                 result.snapshots.size(), p.snapshot_times.size());
  if (result.stop_reason == sim::StopReason::collapse)
    throw std::runtime_error("run stopped early: " + sim::stop_message(result) +
                             " (partial results in " + options.out + ")");
}

// The run's relaxation. Not given: its method's default. Given by a --config file that a run of a
// method that does not relax wrote, to a run that relaxes: the default as well, with a note
// (take_default_over_forced_relaxation, the rule the sweep shares).
void choose_relaxation(sim::Parameters& p, const CLI::Option& relax, const std::string& config) {
  if (relax.count() == 0) {
    sim::default_relaxation_for_method(p);
    return;
  }
  const std::string method = upper_case(sim::format_value(p, *sim::find_parameter("method")));
  take_default_over_forced_relaxation(p.relax_collisions_per_particle, relax, config,
                                      sim::method_relaxes(p.method),
                                      "this " + method + " run relaxes");
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  sim::Parameters& p = options->parameters;
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Event-driven MD (or DSMC, --method dsmc) of inelastic hard disks/spheres; writes the T(t) "
      "time series");
  add_parameter_options(cmd, p);  // every row of the parameter table
  cmd->add_option("--out", options->out, "Output CSV file")
      ->check(path_name())
      ->capture_default_str();
#ifdef MOLCHAOS_HAVE_IO
  cmd->add_option("--trajectory", options->trajectory,
                  "H5MD file (.h5) of the configurations at --snapshot-times")
      ->check(path_name());
  cmd->add_option("--xyz", options->xyz,
                  "Extended XYZ file of the configurations at --snapshot-times, one frame each")
      ->check(path_name());
#endif
  cmd->add_option("--pair-correlations", options->pair_correlations,
                  "CSV file of g(r), G_par(r) and G_perp(r) at each of --snapshot-times, all, "
                  "approaching and receding pairs apart (every pair up to half the box: the cost "
                  "grows as N², seconds per snapshot at N = 2·10⁴, minutes at 10⁵; written with "
                  "the run's files, a signal waits for it)")
      ->check(path_name());
  cmd->add_flag("--quiet", options->quiet, "No progress display");
  sim::CheckpointOptions& checkpoints = options->checkpoints;
  cmd->add_option("--checkpoint", checkpoints.path,
                  "Checkpoint file, written atomically at the intervals below and on SIGTERM or "
                  "SIGINT (then the run ends with exit status 3); not during the relaxation, "
                  "which a signal ends at once without one")
      ->check(path_name());
  cmd->add_option("--checkpoint-interval", checkpoints.interval,
                  "Simulated time between checkpoints (taken at the first sample time after it; "
                  "0 = none) [sigma sqrt(m/T0)]")
      ->transform(real_in(0, true, std::numeric_limits<double>::infinity(), false));
  cmd->add_option("--checkpoint-wall", checkpoints.wall_interval,
                  "Wall-clock seconds between checkpoints (0 = none)")
      ->transform(real_in(0, true, std::numeric_limits<double>::infinity(), false));
  cmd->add_option("--restart", checkpoints.restart,
                  "Continue the run saved in this checkpoint, its parameters taken from the file "
                  "where no flag or --config gives them (only t_end may change): the output is "
                  "byte for byte the uninterrupted run's")
      ->check(path_name());
  cmd->add_option("--write-config", options->write_config,
                  "Also write the run's parameters as a TOML file that --config reads back")
      ->check(path_name());
  const CLI::Option* relax =
      cmd->get_option(std::string(sim::find_parameter("relax_collisions_per_particle")->flag));
  set_callback_with_config(cmd, [cmd, options, relax](const std::string& config) {
    options->config = config;
    // A restart takes the run's parameters from its checkpoint's head, as --config would, where
    // neither a flag nor a --config file gives them (both were read already, and win):
    // `simulate --restart run.ckpt --t-end 200`, or a --config file that gives only t_end.
    if (const std::string& restart = options->checkpoints.restart;
        sim::is_checkpoint_file(restart)) {
      try {
        apply_config_file(cmd, restart);
      } catch (const UsageError& e) {  // the file came by --restart: named so
        const std::string_view prefix = "--config: ", message = e.what();
        if (!message.starts_with(prefix)) throw;
        throw UsageError("--restart", std::string(message.substr(prefix.size())));
      }
    }
    choose_relaxation(options->parameters, *relax, config);
    run_simulate(*options);
  });
}

}  // namespace molchaos::app
