// `molchaos bench`: work–precision measurements that need the whole suite (the per-function
// timings live in bench/ as Google Benchmark programs).
//  --theory      CPU time of the full μ2 coefficient table for the fixed Gauss rules (by order)
//                and the adaptive reference (by requested tolerance), with the error reached
//                (against the closed forms) and estimated.
//  --simulation  error of A for the molecular-chaos (flux) gas, where kinetic theory is exact,
//                against CPU seconds, as N and the number of seeds vary.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <utility>

#include "cli_support.hpp"
#include "commands.hpp"
#include "config_file.hpp"
#include "interrupt_signals.hpp"
#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/reference_values.hpp"
#include "molchaos/validation/ensemble.hpp"
#include "molchaos/validation/estimator_study.hpp"
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
  std::vector<long long> particles{1000, 3000, 10000, 30000, 100000};
  long long work = 400000;  // particle-runs per N
  int threads = 0;
  std::string simulation_flag_given;  // --particles, --work or --threads: for --simulation only
};

// The table, then its figures, with SIGINT and SIGTERM held back (interrupt_signals.hpp): the
// table is written whole, a figure being drawn ends its gnuplot and removes its temporaries, and
// the command then ends by the signal, saying what is in place. During the measurements a signal
// ends the command at once: nothing is written until they are done. `draw(ro)` draws the figures
// named `figures` (file names without extension); an earlier run's files of them are removed
// first, so that an interrupted run leaves no figure of other measurements beside its table.
template <class Draw>
void write_table_and_figures(const BenchOptions& o, const std::string& table,
                             const std::string& csv, const std::vector<std::string>& figures,
                             [[maybe_unused]] Draw&& draw) {
  interrupt_signals::under_way().store(true);
  for (const std::string& figure : figures)
    for (const char* extension : {".png", ".pdf", ".gp"}) {
      std::error_code ignored;
      std::filesystem::remove(std::filesystem::path(o.out) / (figure + extension), ignored);
    }
  const std::string path = (std::filesystem::path(o.out) / table).string();
  validation::write_file_atomically(path, csv);  // first: a figure that cannot be drawn keeps it
  std::string stopped = "after writing " + path;
#ifdef MOLCHAOS_HAVE_FIGURES
  figures::RenderOptions ro;
  ro.output_directory = o.out;
  ro.interrupt = &interrupt_signals::requested();
  try {
    draw(ro);
  } catch (const figures::Interrupted& e) {
    stopped =
        std::string("while ") + e.what() + " (its temporary files removed; " + path + " written)";
  }
#endif
  if (interrupt_signals::requested().load()) {
    std::cout.flush();
    std::cerr << "molchaos: bench stopped by " << interrupt_signals::signal_name() << ' ' << stopped
              << '\n';
    interrupt_signals::end_by_signal();
  }
  interrupt_signals::under_way().store(false);
}

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// CPU seconds per call of `work`, repeated until the clock has seen at least 50 ms.
template <class Work>
double seconds_per_call(Work&& work) {
  int calls = 0;
  const double start = cpu_seconds();
  double elapsed = 0.0;
  do {
    work();
    ++calls;
    elapsed = cpu_seconds() - start;
  } while (elapsed < 0.05);
  return elapsed / calls;
}

// One row of the theory work–precision table: the μ2 table (printed dyad, ε = 1/2) with one
// quadrature setting, its cost and its error against the closed forms.
struct TheoryRow {
  std::string method, setting;
  double seconds = 0.0;
  theory::reference::TableError error;
  std::size_t evaluations = 0;
};

TheoryRow theory_row(int d, const theory::QuadratureOptions& q, std::string method,
                     std::string setting) {
  theory::ExpansionTable table;
  TheoryRow row;
  row.method = std::move(method);
  row.setting = std::move(setting);
  row.seconds =
      seconds_per_call([&] { table = theory::expand_collision_moment(d, 2, 0.5, 3.0, q); });
  row.error = theory::reference::table_error(table);
  row.evaluations = table.integrand_evaluations;
  return row;
}

void bench_theory(const BenchOptions& o) {
  std::string csv =
      fmt::format("# molchaos bench --theory\n# version = {}\n# theory = true\n", k_version);
  csv +=
      "dimension,method,setting,cpu_seconds,max_error_reached,max_error_estimate,integrand_"
      "evaluations\n";
  std::cout << fmt::format("{:>4} {:>9} {:>16} {:>11} {:>14} {:>14} {:>12}\n", "d", "method",
                           "setting", "cpu [s]", "error reached", "error estim.", "evaluations");
  std::vector<validation::WorkPrecisionData> figures_data;  // drawn once the table is written
  for (int d : {2, 3}) {
    validation::WorkPrecisionData& data = figures_data.emplace_back();
    data.title = fmt::format("mu2 coefficient table, d = {} (adaptive QAGIU)", d);
    std::vector<TheoryRow> rows;
    // The reference: nested adaptive QAGIU at requested tolerances.
    for (int k = 4; k <= 12; k += 2) {
      theory::QuadratureOptions q;
      q.method = theory::QuadratureMethod::adaptive;
      q.relative_tolerance = std::pow(10.0, -k);
      rows.push_back(theory_row(d, q, "adaptive", fmt::format("tol {:.0e}", q.relative_tolerance)));
      data.points.push_back({q.relative_tolerance, rows.back().seconds,
                             rows.back().error.reached, rows.back().error.estimated});
    }
    // The default: Gauss–Laguerre rules of rising order (exact from order 4), exact Hermite sum;
    // the value is the higher rule's, the estimate its difference to the lower one.
    for (int order = 1; order <= 5; ++order) {
      theory::QuadratureOptions q;
      q.laguerre_order = order;
      rows.push_back(theory_row(d, q, "gauss", fmt::format("laguerre {}/{}", order, order + 1)));
    }
    for (const TheoryRow& r : rows) {
      std::cout << fmt::format("{:>4} {:>9} {:>16} {:>11.3e} {:>14.2e} {:>14.2e} {:>12}\n", d,
                               r.method, r.setting, r.seconds, r.error.reached, r.error.estimated,
                               r.evaluations);
      csv += fmt::format("{},{},{},{:.4e},{:.3e},{:.3e},{}\n", d, r.method, r.setting, r.seconds,
                         r.error.reached, r.error.estimated, r.evaluations);
    }
  }
  std::vector<std::string> figure_names;
  for (std::size_t k = 0; k < figures_data.size(); ++k)
    figure_names.push_back(fmt::format("work_precision_theory_d{}", k + 2));
  write_table_and_figures(o, "work_precision_theory.csv", csv, figure_names, [&](const auto& ro) {
#ifdef MOLCHAOS_HAVE_FIGURES
    for (std::size_t k = 0; k < figures_data.size(); ++k)
      figures::render_work_precision(figures_data[k], ro, figure_names[k]);
#endif
  });
}

// Seeds for system size n: the same work (particle-runs) for every N, at least k_min_seeds.
constexpr int k_min_seeds = 4;
int seeds_for(const BenchOptions& o, long long n) {
  return static_cast<int>(std::max<long long>(k_min_seeds, (o.work + n - 1) / n));
}

// Cheapest CPU seconds to reach relative standard error r with runs of this size, and the seeds
// that takes (at least 2, so that the error itself can be estimated).
std::pair<double, int> cost_to_reach(const validation::SimulationCostPoint& p, double r) {
  const int seeds = std::max(2, static_cast<int>(std::ceil(std::pow(p.relative_sd_per_run / r, 2))));
  return {seeds * p.cpu_seconds_per_run, seeds};
}

void bench_simulation(const BenchOptions& o) {
  // The flux-shuffled gas obeys molecular chaos, so theory's A is the exact answer. For each N
  // the same work (particle-runs) is spent; the scatter of A over the runs and the CPU seconds
  // per run give, for any target relative standard error r, the seeds and seconds needed,
  // (sd/r)^2 runs; the mean over the runs against theory bounds the finite-N bias.
  // The options as "# key = value" lines: `bench --config` on this file repeats the measurement.
  std::string csv = fmt::format(
      "# molchaos bench --simulation: flux gas, d = 2, n = 0.05, eps = 0.9, runs of 4 tau0; "
      "work in particle-runs per N, seeds max({}, work / N)\n"
      "# version = {}\n# simulation = true\n# particles = {}\n# work = {}\n# threads = {}\n",
      k_min_seeds, k_version, fmt::join(o.particles, " "), o.work, o.threads);
  csv +=
      "particles,seeds,cpu_seconds_per_run,A,A_err,A_theory,relative_bias,relative_bias_error,"
      "relative_sd_per_run,cpu_seconds_for_0.5pc,seeds_for_0.5pc,cpu_seconds_for_0.1pc,seeds_for_"
      "0.1pc\n";
  std::cout << fmt::format("{:>7} {:>5} {:>9} {:>18} {:>20} {:>9} {:>16} {:>16}\n", "N", "seeds",
                           "cpu/run", "A", "rel. bias", "rel. sd", "0.5 %: s (seeds)",
                           "0.1 %: s (seeds)");
  validation::SimulationWorkPrecisionData data;
  std::string estimator_lines;  // after the table, so that the CSV's rows stay together
  data.title = "flux gas, d = 2, n = 0.05, {/Symbol e} = 0.9: standard error of A against cost";
  for (long long n : o.particles) {
    validation::EnsembleSpec spec;
    spec.particles = n;
    spec.densities = {0.05};
    spec.restitutions = {0.9};
    spec.modes = {sim::Randomization::flux};
    spec.seeds = seeds_for(o, n);
    spec.base_seed = 1000;  // not the seeds make reproduce uses
    spec.contact_statistics = false;
    validation::SweepOptions so;
    so.threads = o.threads;
    so.progress = true;
    so.label = fmt::format("bench N = {}", n);
    so.version = k_version;
    const double start = cpu_seconds();
    const auto points = validation::summarize(
        spec, validation::run_sweep(validation::expand(spec), so), validation::WindowRule{});
    const double seconds = cpu_seconds() - start;  // all threads: CPU, not wall time
    const auto& s = points.at(0).summary;
    const double theory = points.at(0).A_theory.value;
    if (s.runs < 2) throw std::runtime_error(fmt::format("bench: N = {}: fewer than 2 fitted runs", n));
    validation::SimulationCostPoint p;
    p.particles = n;
    p.seeds = s.runs;
    p.cpu_seconds_per_run = seconds / spec.seeds;
    // Relative to the measured A, as the estimators' line below and every SE(A)/A of the suite
    // (relative to theory's A, at N = 100 the two costs differed by 9 %).
    p.relative_sd_per_run = s.A.error * std::sqrt(static_cast<double>(s.runs)) / s.A.value;
    p.relative_bias = (s.A.value - theory) / theory;
    p.relative_bias_error = s.A.error / theory;
    data.points.push_back(p);
    const auto [t05, n05] = cost_to_reach(p, 5e-3);
    const auto [t01, n01] = cost_to_reach(p, 1e-3);
    // The same runs through every τ0 estimator: CPU seconds to 0.1 % with each (paired: the
    // difference is the estimator's alone, not the runs').
    std::string by_estimator;
    for (const auto& e : validation::compare_estimator_scatter({&s})) {
      validation::SimulationCostPoint q = p;
      q.relative_sd_per_run = e.relative_sd_per_run;
      by_estimator += fmt::format("{}{} {:.1f} s", by_estimator.empty() ? "" : ", ",
                                  validation::to_string(e.estimator), cost_to_reach(q, 1e-3).first);
    }
    const std::string estimator_line =
        fmt::format("N = {}: CPU seconds to 0.1 % on A by estimator (same runs): {}", n,
                    by_estimator);
    std::cout << fmt::format(
        "{:>7} {:>5} {:>9.3f} {:>9.4f} ± {:<6.4f} {:>+9.2e} ± {:<8.1e} {:>9.2e} {:>8.1f} ({:>5}) "
        "{:>8.1f} ({:>5})\n",
        n, p.seeds, p.cpu_seconds_per_run, s.A.value, s.A.error, p.relative_bias,
        p.relative_bias_error, p.relative_sd_per_run, t05, n05, t01, n01);
    csv += fmt::format("{},{},{:.4f},{:.6f},{:.6f},{:.6f},{:.4e},{:.4e},{:.4e},{:.2f},{},{:.2f},{}\n",
                       n, p.seeds, p.cpu_seconds_per_run, s.A.value, s.A.error, theory,
                       p.relative_bias, p.relative_bias_error, p.relative_sd_per_run, t05, n05,
                       t01, n01);
    std::cout << "  " << estimator_line << '\n';
    estimator_lines += "# " + estimator_line + '\n';
  }
  // The scatter of A over runs falls as 1/sqrt(N) (independent particles); pooling sd * sqrt(N)
  // over every N (weighted by degrees of freedom) estimates it far better than the few seeds of the
  // largest N alone, so the recommendation uses the pooled value: for each target the cheapest N
  // among those whose measured bias is consistent with zero (within 2 standard errors) and
  // resolved below the target.
  double sum_dof = 0, sum_var = 0;
  for (const auto& p : data.points) {
    sum_dof += p.seeds - 1;
    sum_var += (p.seeds - 1) * p.relative_sd_per_run * p.relative_sd_per_run *
               static_cast<double>(p.particles);
  }
  csv += estimator_lines;
  const double pooled = std::sqrt(sum_var / sum_dof);  // relative sd per run times sqrt(N)
  const std::string pooled_line =
      fmt::format("pooled relative sd per run x sqrt(N) = {:.3f} ({} degrees of freedom)", pooled,
                  static_cast<int>(sum_dof));
  std::cout << pooled_line << '\n';
  csv += "# " + pooled_line + '\n';
  for (double r : data.targets) {
    const validation::SimulationCostPoint* best = nullptr;
    std::pair<double, int> best_cost{0.0, 0};
    for (const auto& p : data.points) {
      const bool unbiased = std::fabs(p.relative_bias) <= 2 * p.relative_bias_error &&
                            2 * p.relative_bias_error < r;
      validation::SimulationCostPoint q = p;
      q.relative_sd_per_run = pooled / std::sqrt(static_cast<double>(p.particles));
      const auto cost = cost_to_reach(q, r);
      if (unbiased && (best == nullptr || cost.first < best_cost.first)) {
        best = &p;
        best_cost = cost;
      }
    }
    const std::string line =
        best == nullptr
            ? fmt::format("target {:.1f} %: no N has its bias resolved below the target at this "
                          "work (raise --work)",
                          100 * r)
            : fmt::format("target {:.1f} %: cheapest N = {} with {} seeds, {:.1f} CPU s "
                          "(pooled scatter; bias {:+.2e} ± {:.1e})",
                          100 * r, best->particles, best_cost.second, best_cost.first,
                          best->relative_bias, best->relative_bias_error);
    std::cout << line << '\n';
    csv += "# " + line + '\n';
  }
#ifdef MOLCHAOS_HAVE_FIGURES
  const std::vector<std::string> figure_names{figures::k_simulation_cost_figure};
#else
  const std::vector<std::string> figure_names;
#endif
  write_table_and_figures(o, "work_precision_simulation.csv", csv, figure_names,
                          [&](const auto& ro) {
#ifdef MOLCHAOS_HAVE_FIGURES
    figures::render_simulation_cost(data, ro);
#endif
  });
}

void run_bench(const BenchOptions& o) {
  if (!o.theory && !o.simulation) throw UsageError("bench", "choose --theory and/or --simulation");
  if (!o.simulation && !o.simulation_flag_given.empty())  // would be dropped without a word
    throw UsageError(o.simulation_flag_given, "applies to --simulation only");
  reject_repeated_values("--particles", o.particles,
                         "each N once (the pooled scatter takes every N's runs as independent)");
  // Created, and a file written in it, before the work; removed again by a signal that ends the
  // measurements, which write nothing until they are done.
  interrupt_signals::remove_if_empty_when_ended_early(require_usable_directory("--out", o.out));
  interrupt_signals::install(
      "molchaos: bench interrupted during its measurements; nothing written (a table is written "
      "once its measurements are done), and the same command measures again from the start\n");
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
                "flux gas: error of A vs CPU seconds over N (same work each)");
  CLI::Option* particles = add_list_option(cmd, "--particles", o->particles,
                                           "N values (comma separated)", integer_in(100, 10000000));
  CLI::Option* work =
      cmd->add_option("--work", o->work, "particle-runs per N (seeds = max(4, work / N))")
          ->transform(integer_in(1000, 1000000000))
          ->capture_default_str();
  CLI::Option* threads =
      cmd->add_option("--threads", o->threads, "worker threads of --simulation (0: all cores)")
          ->transform(integer_in(0, 1024))
          ->capture_default_str();
  cmd->add_option("--out", o->out, "output folder")->check(path_name())->capture_default_str();
  set_callback_with_config(cmd, [cmd, o, particles, work, threads](const std::string& config) {
    if (particles->count() > 0) o->simulation_flag_given = "--particles";
    if (work->count() > 0) o->simulation_flag_given = "--work";
    if (threads->count() > 0) o->simulation_flag_given = "--threads";
    require_config_table_kept(*cmd, config, o->out);
    run_bench(*o);
  });
}

}  // namespace molchaos::app
