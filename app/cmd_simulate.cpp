// `molchaos simulate`: flags -> sim::Parameters (validated once), run, write the CSV atomically.
// No physics here.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli_support.hpp"
#include "commands.hpp"
#include "molchaos/sim/sim.hpp"
#ifdef MOLCHAOS_HAVE_IO
#include "molchaos/io/h5md_writer.hpp"
#include "molchaos/io/xyz_writer.hpp"
#endif

namespace molchaos::app {
namespace {

struct SimulateOptions {
  sim::Parameters parameters;
  std::string randomize = "none";
  std::string out = "run.csv";
  std::string trajectory;  // H5MD file of the snapshots (empty: none)
  std::string xyz;         // extended XYZ file of the snapshots (empty: none)
  bool quiet = false;
};

std::string snapshot_path(const std::string& out, std::size_t index) {
  const auto dot = out.rfind('.');
  const std::string stem = (dot == std::string::npos || dot == 0) ? out : out.substr(0, dot);
  return stem + ".snapshot" + std::to_string(index) + ".csv";
}

void run_simulate(const SimulateOptions& options) {
  sim::Parameters p = options.parameters;
  const auto mode = sim::parse_randomization(options.randomize);
  if (!mode)
    throw UsageError("--randomize",
                     "unknown value '" + options.randomize + "'; allowed: none, paper, flux");
  p.randomize = *mode;
  require_writable_file("--out", options.out, /*create_parent=*/false);
  if (!options.trajectory.empty()) require_writable_file("--trajectory", options.trajectory, false);
  if (!options.xyz.empty()) require_writable_file("--xyz", options.xyz, false);
  try {
    sim::validate(p);
  } catch (const std::invalid_argument& e) {
    throw_as_usage_error("simulate", e.what());  // validate() names fields; the user typed flags
  }

  const bool show_progress = !options.quiet && ::isatty(::fileno(stderr)) != 0;
  sim::ProgressReporter progress;
  if (show_progress)
    progress = [](const sim::Progress& report) {
      const double rate = report.wall_seconds > 0
                              ? static_cast<double>(report.collisions) / report.wall_seconds
                              : 0.0;
      std::fprintf(stderr, "\rsimulate: %5.1f%%  %.3g collisions  %.3g M collisions/s   ",
                   100.0 * std::min(1.0, report.fraction_done),
                   static_cast<double>(report.collisions), rate / 1e6);
      std::fflush(stderr);
    };
  const sim::RunResult result = sim::run_with_progress(p, progress);
  if (show_progress) std::fprintf(stderr, "\n");

  sim::write_csv_file(result, options.out);
  for (std::size_t k = 0; k < result.snapshots.size(); ++k) {
    const std::string path = snapshot_path(options.out, k);
    const std::string temporary = path + ".tmp";
    {
      std::ofstream file(temporary);
      sim::write_snapshot_csv(result.snapshots[k], p.dimension, file);
      if (!file) throw std::runtime_error("cannot write " + temporary);
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      throw std::runtime_error("cannot rename " + temporary + " to " + path);
  }
#ifdef MOLCHAOS_HAVE_IO
  if (!options.trajectory.empty()) io::write_h5md_file(result, options.trajectory);
  if (!options.xyz.empty()) io::write_xyz_file(result, options.xyz);
#endif
  std::fprintf(stderr, "simulate: %llu collisions in %.2f s, stop: %s, wrote %s\n",
               static_cast<unsigned long long>(result.collisions), result.wall_seconds,
               sim::stop_message(result).c_str(), options.out.c_str());
  if (result.stop_reason == sim::StopReason::collapse)
    throw std::runtime_error("run stopped early: " + sim::stop_message(result) +
                             " (partial results in " +
                             options.out + ")");
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  sim::Parameters& p = options->parameters;
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Event-driven MD of inelastic hard disks/spheres; writes the T(t) time series");
  constexpr double inf = std::numeric_limits<double>::infinity();
  cmd->add_option("--dim", p.dimension, "Dimension d")
      ->check(integer_in(2, 3))
      ->capture_default_str();
  cmd->add_option("--particles", p.particles, "Number of particles N")
      ->check(integer_in(2, 100000000))
      ->capture_default_str();
  cmd->add_option(
         "--density", p.density,
         "Reduced density n = N sigma^d / V, in (0, close packing): (0, 1.1547) for d = 2, "
         "(0, 1.41421) for d = 3")
      ->check(real_in(0, false, inf, false))
      ->capture_default_str();
  cmd->add_option("--restitution", p.restitution, "Coefficient of restitution")
      ->check(real_in(0, false, 1, true))
      ->capture_default_str();
  cmd->add_option("--randomize", options->randomize, "Velocity shuffle: none, paper, flux")
      ->capture_default_str();
  cmd->add_option("--seed", p.seed, "Random seed")
      ->check(unsigned_integer())
      ->capture_default_str();
  cmd->add_option("--t-end", p.t_end, "Physical duration of the cooling run")
      ->check(real_in(0, false, inf, false))
      ->capture_default_str();
  cmd->add_option("--relax", p.relax_collisions_per_particle,
                  "Elastic collisions per particle before t = 0")
      ->check(real_in(0, true, inf, false))
      ->capture_default_str();
  cmd->add_option("--tc", p.tc, "TC model duration (0 = off)")
      ->check(real_in(0, true, inf, false))
      ->capture_default_str();
  cmd->add_option("--samples-per-decade", p.samples_per_decade, "Samples per decade of time")
      ->check(integer_in(1, 10000))
      ->capture_default_str();
  cmd->add_option("--t-first-sample", p.t_first_sample, "First log-spaced sample time")
      ->check(real_in(0, false, inf, false))
      ->capture_default_str();
  cmd->add_flag("--contacts", p.contact_statistics, "Record contact statistics of collisions");
  cmd->add_option("--snapshot-times", p.snapshot_times,
                  "Times of position/velocity snapshots (written next to --out)")
      ->check(real_in(0, true, inf, false));
  cmd->add_option("--max-collisions", p.max_collisions, "Stop after this many collisions (0 = no)")
      ->check(unsigned_integer())
      ->capture_default_str();
  cmd->add_option("--min-temperature", p.min_temperature, "Stop when T/T0 falls below (0 = no)")
      ->check(real_in(0, true, 1, false))
      ->capture_default_str();
  cmd->add_option("--out", options->out, "Output CSV file")->capture_default_str();
#ifdef MOLCHAOS_HAVE_IO
  cmd->add_option("--trajectory", options->trajectory,
                  "H5MD file (.h5) of the configurations at --snapshot-times");
  cmd->add_option("--xyz", options->xyz,
                  "Extended XYZ file of the configurations at --snapshot-times, one frame each");
#endif
  cmd->add_flag("--quiet", options->quiet, "No progress display");
  cmd->callback([options] { run_simulate(*options); });
}

}  // namespace molchaos::app
