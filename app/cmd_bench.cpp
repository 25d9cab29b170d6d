// `molchaos bench`: work–precision measurements that need the whole suite (the per-function
// timings live in bench/ as Google Benchmark programs).
//  --theory      CPU time of the full μ2 coefficient table against the requested quadrature
//                tolerance, with the error reached (against the closed forms) and estimated.
//  --simulation  error of A for the molecular-chaos (flux) gas, where kinetic theory is exact,
//                against CPU seconds, as N and the number of seeds vary.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli_support.hpp"
#include "commands.hpp"
#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/reference_values.hpp"
#include "molchaos/validation/ensemble.hpp"
#include "molchaos/validation/report.hpp"
#include "molchaos/version.hpp"
#ifdef MOLCHAOS_HAVE_FIGURES
#include "molchaos/figures/render.hpp"
#endif

namespace molchaos::app {
namespace {

struct BenchOptions {
  std::string out = "results/bench";
  bool theory = false;
  bool simulation = false;
  std::vector<long long> particles{1000, 3000, 10000};
  std::vector<int> seeds{2, 4, 8};
};

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

void bench_theory(const BenchOptions& o) {
  std::string csv = fmt::format("# molchaos bench --theory\n# version = {}\n", k_version);
  csv +=
      "dimension,requested_tolerance,cpu_seconds,max_error_reached,max_error_estimate,integrand_"
      "evaluations\n";
  std::cout << fmt::format("{:>4} {:>10} {:>10} {:>14} {:>14} {:>12}\n", "d", "tolerance",
                           "cpu [s]", "error reached", "error estim.", "evaluations");
  for (int d : {2, 3}) {
    validation::WorkPrecisionData data;
    data.title = fmt::format("mu2 coefficient table, d = {}", d);
    for (int k = 4; k <= 12; k += 2) {
      theory::QuadratureOptions q;
      q.relative_tolerance = std::pow(10.0, -k);
      const double start = cpu_seconds();
      const auto table = theory::expand_collision_moment(d, 2, 0.5, 3.0, q);
      const double seconds = cpu_seconds() - start;
      const auto [reached, estimate] = theory::reference::table_error(table);
      data.points.push_back({q.relative_tolerance, seconds, reached, estimate});
      std::cout << fmt::format("{:>4} {:>10.0e} {:>10.3f} {:>14.2e} {:>14.2e} {:>12}\n", d,
                               q.relative_tolerance, seconds, reached, estimate,
                               table.integrand_evaluations);
      csv += fmt::format("{},{:.0e},{:.4f},{:.3e},{:.3e},{}\n", d, q.relative_tolerance, seconds,
                         reached, estimate, table.integrand_evaluations);
    }
#ifdef MOLCHAOS_HAVE_FIGURES
    figures::RenderOptions ro;
    ro.output_directory = o.out;
    figures::render_work_precision(data, ro, fmt::format("work_precision_theory_d{}", d));
#endif
  }
  validation::write_file_atomically(
      (std::filesystem::path(o.out) / "work_precision_theory.csv").string(), csv);
}

void bench_simulation(const BenchOptions& o) {
  // The flux-shuffled gas obeys molecular chaos, so theory's A is the exact answer: the error of
  // the ensemble mean against it, and its standard error, against the CPU time spent.
  std::string csv = fmt::format(
      "# molchaos bench --simulation: flux gas, d = 2, n = 0.05, eps = 0.9\n# version = {}\n",
      k_version);
  csv += "particles,seeds,cpu_seconds,A,A_err,A_theory,relative_error,relative_standard_error\n";
  std::cout << fmt::format("{:>9} {:>6} {:>10} {:>10} {:>9} {:>12} {:>12}\n", "N", "seeds",
                           "cpu [s]", "A", "A_err", "rel. error", "rel. SE");
  for (long long n : o.particles)
    for (int seeds : o.seeds) {
      validation::EnsembleSpec spec;
      spec.particles = n;
      spec.densities = {0.05};
      spec.restitutions = {0.9};
      spec.modes = {sim::Randomization::flux};
      spec.seeds = seeds;
      spec.contact_statistics = false;
      validation::SweepOptions so;
      so.threads = 1;
      so.progress = false;
      so.version = k_version;
      const auto start = std::chrono::steady_clock::now();
      const auto points = validation::summarize(
          spec, validation::run_sweep(validation::expand(spec), so), validation::WindowRule{});
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const auto& p = points.at(0);
      const double rel = (p.summary.A.value - p.A_theory.value) / p.A_theory.value;
      const double rel_se = p.summary.A.error / p.A_theory.value;
      std::cout << fmt::format("{:>9} {:>6} {:>10.2f} {:>10.4f} {:>9.4f} {:>12.2e} {:>12.2e}\n", n,
                               seeds, seconds, p.summary.A.value, p.summary.A.error, rel, rel_se);
      csv += fmt::format("{},{},{:.3f},{:.6f},{:.6f},{:.6f},{:.4e},{:.4e}\n", n, seeds, seconds,
                         p.summary.A.value, p.summary.A.error, p.A_theory.value, rel, rel_se);
    }
  validation::write_file_atomically(
      (std::filesystem::path(o.out) / "work_precision_simulation.csv").string(), csv);
}

void run_bench(const BenchOptions& o) {
  if (!o.theory && !o.simulation) throw UsageError("bench", "choose --theory and/or --simulation");
  require_writable_directory("--out", o.out);
  std::filesystem::create_directories(o.out);
  if (o.theory) bench_theory(o);
  if (o.simulation) bench_simulation(o);
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Work-precision measurements (theory quadrature, simulation ensembles)");
  cmd->add_flag("--theory", o->theory,
                "coefficient table: CPU time vs tolerance and error reached");
  cmd->add_flag("--simulation", o->simulation,
                "flux gas: error of A vs CPU seconds over N and seeds");
  cmd->add_option("--particles", o->particles, "N values (comma separated)")
      ->delimiter(',')
      ->check(integer_in(100, 10000000));
  cmd->add_option("--seeds", o->seeds, "seed counts (comma separated)")
      ->delimiter(',')
      ->check(integer_in(1, 10000));
  cmd->add_option("--out", o->out, "output folder")->capture_default_str();
  cmd->callback([o] { run_bench(*o); });
}

}  // namespace molchaos::app
