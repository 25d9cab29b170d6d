// `molchaos reproduce`: regenerates the paper's results into one folder: the figures, REPORT.md,
// REPORT.html, fig4_A_of_eps.csv, a2_of_eps.csv. Runs are cached in <out>/cache, so an interrupted
// reproduction resumes.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli_support.hpp"
#include "commands.hpp"
#include "config_file.hpp"
#include "interrupt_signals.hpp"
#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/relaxed_states.hpp"
#include "molchaos/validation/report.hpp"
#include "molchaos/validation/report_html.hpp"
#include "molchaos/validation/reproduce.hpp"
#include "molchaos/version.hpp"
#include "sweep_runner.hpp"
#ifdef MOLCHAOS_HAVE_FIGURES
#include "molchaos/figures/render.hpp"
#endif

namespace molchaos::app {
namespace {

struct ReproduceCliOptions {
  std::string out = "results";
  std::string cache;
  bool quick = false;
  int seeds = 0;
  std::uint64_t base_seed = validation::ReproduceConfig{}.base_seed;
  int threads = 0;
  bool no_figures = false;
  bool relax_each_run = false;
  bool quiet = false;
};

// SIGINT and SIGTERM (interrupt_signals.hpp). During the runs (and the analyses between them) a
// signal ends the command at once: every finished run is in the cache already, written whole
// (temporary name, then rename), so the handler only says so. From the figures on, the signal is
// recorded: the figure being rendered ends its gnuplot and removes its temporaries
// (figures::RenderOptions::interrupt), the staged outputs are discarded (StagedOutputs), and the
// command then ends by the signal's default action.
void install_reproduce_signals(const std::string& cache_directory) {
  interrupt_signals::install(fmt::format(
      "molchaos: reproduce interrupted during the runs and analyses; the cache {} keeps every "
      "finished run, and the same command continues from them\n",
      cache_directory));
}

// The outputs of one reproduction (figures, tables, report), written into a staging folder inside
// --out and moved into place together once all are complete: an interrupted or failed
// reproduction leaves the folder's earlier outputs as they were, and a report never stands beside
// figures of another run. The folder has a temporary's name, which remove_stale_temporaries()
// clears after a killed process.
class StagedOutputs {
 public:
  StagedOutputs(std::string out, std::string cache)
      : out_(std::move(out)),
        cache_(std::move(cache)),
        path_(sim::temporary_name((std::filesystem::path(out_) / "reproduce").string())) {
    std::error_code ec;
    std::filesystem::create_directory(path_, ec);
    if (ec) throw std::runtime_error("cannot create " + path_ + ": " + ec.message());
  }
  ~StagedOutputs() { discard(); }
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;

  const std::string& path() const { return path_; }
  const std::string& cache() const { return cache_; }
  void discard() const {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  /// Moves every file into --out, the report last; returns their names.
  std::vector<std::string> commit() const {
    namespace fs = std::filesystem;
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path_))
      names.push_back(entry.path().filename().string());
    std::ranges::sort(names, {}, [](const std::string& name) {
      return std::pair{name.starts_with("REPORT."), name};
    });
    for (const std::string& name : names) fs::rename(fs::path(path_) / name, fs::path(out_) / name);
    return names;
  }

 private:
  std::string out_, cache_, path_;
};

// Ends the command as the recorded signal would have: one line on stderr saying what it stopped,
// then the signal's default action. The staged outputs are discarded: the folder is as before.
[[noreturn]] void end_by_signal(const std::string& stopped, const StagedOutputs& staged) {
  staged.discard();
  std::cout.flush();
  std::fprintf(stderr,
               "molchaos: reproduce stopped by %s %s; the output folder is as it was, the cache "
               "%s keeps every finished run, and the same command writes the figures and the "
               "report from it\n",
               interrupt_signals::signal_name(), stopped.c_str(), staged.cache().c_str());
  interrupt_signals::end_by_signal();
}

void stop_if_interrupted(const std::string& stopped, const StagedOutputs& staged) {
  if (interrupt_signals::requested().load()) end_by_signal(stopped, staged);
}

// Figures and tables in --out that this reproduction did not write (it ran with --no-figures, or
// a quick look into the folder of a paper-scale one, whose break-down figures and tables it has
// not): named, since the report beside them does not describe them. They are the user's to keep
// or remove. A table of a reproduction has the re-run lines under its title (rerun_lines()), the
// first "# quick = ..."; a CSV of the user's own has not.
void note_outputs_of_other_runs(const std::string& out, const std::vector<std::string>& written) {
  const auto reproduction_table = [](const std::filesystem::path& path) {
    std::ifstream in(path);
    std::string title, second;
    return std::getline(in, title) && std::getline(in, second) && second.starts_with("# quick = ");
  };
  std::vector<std::string> others;
  int figures = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(out, ec)) {
    const std::string name = entry.path().filename().string();
    const std::string extension = entry.path().extension().string();
    if (std::ranges::find(written, name) != written.end()) continue;
    const bool figure = name.starts_with("fig") && (extension == ".png" || extension == ".gif");
    if (figure || (extension == ".csv" && reproduction_table(entry.path()))) others.push_back(name);
    figures += figure;
  }
  if (others.empty()) return;
  std::ranges::sort(others);
  std::string list;
  for (const std::string& name : others) list += (list.empty() ? "" : ", ") + name;
  std::cerr << fmt::format(
      "note: {} holds {} figure(s) and {} table(s) of an earlier reproduction, which the new "
      "report does not describe: {}\n",
      out, figures, others.size() - static_cast<std::size_t>(figures), list);
}

// The command line as the report names it: the options that change what the report says. --out,
// --cache, --threads, --quiet and --relax-each-run change where the files go and how fast they
// come, not their content, so the same options give the same report byte for byte; a --seeds or
// --base-seed equal to the default is left out, as the tables' own re-runs (--config) give it.
std::string report_command(const ReproduceCliOptions& o, int default_seeds) {
  std::string command = "molchaos reproduce";
  if (o.quick) command += " --quick";
  if (o.seeds > 0 && o.seeds != default_seeds) command += fmt::format(" --seeds {}", o.seeds);
  if (o.base_seed != validation::ReproduceConfig{}.base_seed)
    command += fmt::format(" --base-seed {}", o.base_seed);
  if (o.no_figures) command += " --no-figures";
  return command;
}

#ifdef MOLCHAOS_HAVE_FIGURES
// The figures' file names (relative to the report). An interrupt ends the command here, with the
// temporaries of the figure under way removed.
std::vector<std::string> render_figures(const validation::ReproduceResults& results,
                                        const figures::RenderOptions& ro,
                                        const StagedOutputs& staged) {
  std::vector<std::string> figure_files;
  const auto keep = [&](const figures::RenderedFigure& f, const char* extension) {
    for (const auto& file : f.files)
      if (file.ends_with(extension))
        figure_files.push_back(std::filesystem::path(file).filename().string());
  };
  try {
    keep(figures::render_fig3(results.fig3, ro), ".png");
    keep(figures::render_fig4(results.fig4, ro), ".png");
    keep(figures::render_b(results.b, ro), ".png");
    keep(figures::render_a2(results.a2, ro), ".png");
    keep(figures::render_snapshot(results.snapshot, ro), ".png");
    keep(figures::render_pair_correlations(results.correlations.pair_correlations, 2, 0.1, 0.8, ro),
         ".png");
    keep(figures::render_contact_moments(results.correlations.contact_moments, ro), ".png");
    keep(figures::render_cooling_decomposition(results.correlations.decomposition, ro), ".png");
    keep(figures::render_impact_parameter(results.correlations.impact_parameter, ro), ".png");
    // The break-down figures exist at paper scale only (the quick look skips their runs).
    if (results.gas_fields.series.empty()) return figure_files;
    const auto spec3 = validation::BreakdownSpec::three_dimensional();
    keep(figures::render_flow_field(results.gas_fields.fields, ro), ".png");
    keep(figures::render_structure_factors(results.breakdown_curves, results.gas_fields, ro),
         ".png");
    keep(figures::render_linear_hydrodynamics(
             results.breakdown_curves_3d,
             fmt::format("d = 3, n = {}, ε = {}", spec3.density, spec3.restitution),
             "fig_structure_factor_3d", ro),
         ".png");
    // The animation needs gnuplot's gif terminal; without it the report says so.
    if (figures::gnuplot_has_terminal("gif", ro))
      keep(figures::render_flow_field_animation(results.gas_fields.animation, ro), ".gif");
  } catch (const figures::Interrupted& e) {
    end_by_signal(fmt::format("while {}", e.what()), staged);
  }
  return figure_files;
}
#endif

void run_reproduce(const ReproduceCliOptions& o) {
  auto cfg = o.quick ? validation::ReproduceConfig::quick_look()
                     : validation::ReproduceConfig::paper_scale();
  const int default_seeds = cfg.seeds;
  if (o.seeds > 0) cfg.seeds = o.seeds;
  cfg.base_seed = o.base_seed;
  if (o.relax_each_run) sim::share_relaxed_states(false);
  // Both folders are created, and a file written in each, before any run: permissions alone do
  // not show /proc or a read-only mount (and root passes them). The cache first, so that a
  // refused --cache leaves no empty --out behind.
  require_writable_directory("--out", o.out);
  if (!o.cache.empty()) require_usable_directory("--cache", o.cache);
  require_usable_directory("--out", o.out);
  validation::SweepOptions sweep;
  sweep.cache_directory =
      o.cache.empty() ? (std::filesystem::path(o.out) / "cache").string() : o.cache;
  sweep.threads = o.threads;
  sweep.version = k_version;
  sweep.runner = default_sweep_runner();
  sweep.label = o.quick ? "reproduce --quick" : "reproduce";
  sweep.progress = !o.quiet;
  // Figures and tables of a killed earlier run, at any age: a writer on this host whose process
  // is gone leaves nothing that anyone finishes (the age rule is for other hosts' writers).
  sim::remove_stale_temporaries(o.out, 0.0);
  install_reproduce_signals(sweep.cache_directory);
  if (!o.quiet)
    std::cerr << fmt::format(
        "[reproduce] {}: N = {}, {} restitutions x {} densities x 3 modes x {} seeds, "
        "plus Fig. 3 and the elastic-limit runs; cache {}\n",
        o.quick ? "quick look" : "paper scale", cfg.particles, cfg.restitutions.size(),
        cfg.densities.size(), cfg.seeds, sweep.cache_directory);
  auto results = validation::reproduce(cfg, sweep);
  interrupt_signals::under_way().store(true);
  validation::withhold_undecidable_verdicts(results.claims, cfg.seeds);

  const StagedOutputs staged(o.out, sweep.cache_directory);
  const std::string& dir = staged.path();
  std::vector<std::string> figure_files;
#ifdef MOLCHAOS_HAVE_FIGURES
  if (!o.no_figures) {
    figures::RenderOptions ro;
    ro.output_directory = dir;
    ro.interrupt = &interrupt_signals::requested();
    figure_files = render_figures(results, ro, staged);
  }
#endif
  stop_if_interrupted("after the figures", staged);
  validation::write_file_atomically((std::filesystem::path(dir) / "fig4_A_of_eps.csv").string(),
                                    validation::fig4_csv(results));
  validation::write_file_atomically((std::filesystem::path(dir) / "fig4_fits.csv").string(),
                                    validation::fig4_fits_csv(results));
  validation::write_file_atomically((std::filesystem::path(dir) / "a2_of_eps.csv").string(),
                                    validation::a2_csv(results));
  validation::write_correlation_tables(results.correlations, dir,
                                       validation::rerun_lines(results.config));
  validation::write_breakdown_tables(results, dir);
  validation::write_estimator_table(results, dir);
  stop_if_interrupted("after the tables", staged);
  const std::string markdown =
      validation::report_markdown(results, figure_files, report_command(o, default_seeds));
  validation::write_file_atomically((std::filesystem::path(dir) / "REPORT.md").string(), markdown);
  // The same report as one self-contained page, figures embedded.
  validation::write_file_atomically((std::filesystem::path(dir) / "REPORT.html").string(),
                                    validation::report_html(markdown, dir));
  stop_if_interrupted("after writing the report", staged);
  const std::vector<std::string> written = staged.commit();
  std::cout << fmt::format(
      "wrote {}/REPORT.md, {}/REPORT.html, the tables behind them ({}/*.csv) "
      "and {} figures in {:.0f} s{}\n",
      o.out, o.out, o.out, figure_files.size(), results.seconds,
      o.quick ? " (a quick look: --quick)" : "");
  std::cout << fmt::format(
      "{} claims, {} of them not reproduced or contradicted (see the summary of the report)\n",
      results.claims.size(), validation::count_not_reproduced(results));
  std::cout.flush();
  note_outputs_of_other_runs(o.out, written);
  if (results.failed_runs > 0)
    throw std::runtime_error(
        fmt::format("{} run(s) failed; see {}/REPORT.md", results.failed_runs, o.out));
}

}  // namespace

void add_reproduce_command(CLI::App& app) {
  auto o = std::make_shared<ReproduceCliOptions>();
  CLI::App* cmd =
      app.add_subcommand("reproduce", "Regenerate the paper's figures, REPORT.md and tables");
  cmd->add_option("--out", o->out, "output folder")->check(path_name())->capture_default_str();
  cmd->add_option("--cache", o->cache, "run cache (default <out>/cache)")->check(path_name());
  cmd->add_flag("--quick", o->quick, "a first look in seconds (N = 1000, 3 restitutions, 3 seeds)");
  cmd->add_option("--seeds", o->seeds, "seeds per point (default: 8, quick 3)")
      ->transform(integer_in(1, 10000));
  cmd->add_option("--base-seed", o->base_seed,
                  "base seed: a run's seed is a hash of it and the run's index; the studies "
                  "with bases of their own have them shifted by base seed - 1")
      ->transform(unsigned_integer())
      ->capture_default_str();
  CLI::Option* threads = cmd->add_option("--threads", o->threads, "worker threads (0: all cores)")
                             ->transform(integer_in(0, 1024));
  cmd->add_flag("--no-figures", o->no_figures, "skip rendering");
  cmd->add_flag("--quiet", o->quiet, "no progress on stderr (notes and errors still)");
  cmd->add_flag("--relax-each-run", o->relax_each_run,
                "relax every run itself instead of restoring the relaxed state of an earlier run "
                "with the same N, density and seed (the same results, more CPU)");
  set_callback_with_config(cmd, [cmd, o, threads](const std::string& config) {
    reject_threads_on_ranks(threads->count() > 0);
    require_config_table_kept(*cmd, config, o->out);
    run_reproduce(*o);
  });
}

}  // namespace molchaos::app
