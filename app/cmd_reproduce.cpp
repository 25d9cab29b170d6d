// `molchaos reproduce`: regenerates the paper's results into one folder: the figures, REPORT.md,
// REPORT.html, fig4_A_of_eps.csv, a2_of_eps.csv. Runs are cached in <out>/cache, so an interrupted
// reproduction resumes.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli_support.hpp"
#include "commands.hpp"
#include "config_file.hpp"
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
  int threads = 0;
  bool figures = true;
  bool relax_each_run = false;
  bool quiet = false;
};

void run_reproduce(const ReproduceCliOptions& o) {
  auto cfg = o.quick ? validation::ReproduceConfig::quick_look()
                     : validation::ReproduceConfig::paper_scale();
  if (o.seeds > 0) cfg.seeds = o.seeds;
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
  sim::remove_stale_temporaries(o.out);  // figures and tables of a killed earlier run
  if (!o.quiet)
    std::cerr << fmt::format(
        "[reproduce] {}: N = {}, {} restitutions x {} densities x 3 modes x {} seeds, "
        "plus Fig. 3 and the elastic-limit runs; cache {}\n",
        o.quick ? "quick look" : "paper scale", cfg.particles, cfg.restitutions.size(),
        cfg.densities.size(), cfg.seeds, sweep.cache_directory);
  const auto results = validation::reproduce(cfg, sweep);

  std::vector<std::string> figure_files;
#ifdef MOLCHAOS_HAVE_FIGURES
  if (o.figures) {
    figures::RenderOptions ro;
    ro.output_directory = o.out;
    for (const auto& f :
         {figures::render_fig3(results.fig3, ro), figures::render_fig4(results.fig4, ro),
          figures::render_b(results.b, ro), figures::render_a2(results.a2, ro),
          figures::render_snapshot(results.snapshot, ro),
          figures::render_pair_correlations(results.correlations.pair_correlations, 2, 0.1, 0.8,
                                            ro),
          figures::render_contact_moments(results.correlations.contact_moments, ro),
          figures::render_cooling_decomposition(results.correlations.decomposition, ro),
          figures::render_impact_parameter(results.correlations.impact_parameter, ro)})
      for (const auto& file : f.files)
        if (file.ends_with(".png"))
          figure_files.push_back(std::filesystem::path(file).filename().string());
    // The break-down figures exist at paper scale only (the quick look skips their runs).
    if (!results.gas_fields.series.empty()) {
      const auto spec3 = validation::BreakdownSpec::three_dimensional();
      for (const auto& f :
           {figures::render_flow_field(results.gas_fields.fields, ro),
            figures::render_structure_factors(results.breakdown_curves, results.gas_fields, ro),
            figures::render_linear_hydrodynamics(
                results.breakdown_curves_3d,
                fmt::format("d = 3, n = {}, ε = {}", spec3.density, spec3.restitution),
                "fig_structure_factor_3d", ro)})
        for (const auto& file : f.files)
          if (file.ends_with(".png"))
            figure_files.push_back(std::filesystem::path(file).filename().string());
      // The animation needs gnuplot's gif terminal; without it the report says so.
      if (figures::gnuplot_has_terminal("gif", ro))
        for (const auto& file :
             figures::render_flow_field_animation(results.gas_fields.animation, ro).files)
          if (file.ends_with(".gif"))
            figure_files.push_back(std::filesystem::path(file).filename().string());
    }
  }
#endif
  const std::string command = o.quick ? "make reproduce QUICK=1" : "make reproduce";
  validation::write_file_atomically((std::filesystem::path(o.out) / "fig4_A_of_eps.csv").string(),
                                    validation::fig4_csv(results));
  validation::write_file_atomically((std::filesystem::path(o.out) / "a2_of_eps.csv").string(),
                                    validation::a2_csv(results));
  validation::write_correlation_tables(results.correlations, o.out);
  validation::write_breakdown_tables(results, o.out);
  validation::write_estimator_table(results, o.out);
  const std::string markdown = validation::report_markdown(results, figure_files, command);
  validation::write_file_atomically((std::filesystem::path(o.out) / "REPORT.md").string(),
                                    markdown);
  // The same report as one self-contained page, figures embedded.
  validation::write_file_atomically((std::filesystem::path(o.out) / "REPORT.html").string(),
                                    validation::report_html(markdown, o.out));
  std::cout << fmt::format(
      "wrote {}/REPORT.md, {}/REPORT.html, {}/fig4_A_of_eps.csv, {}/a2_of_eps.csv and {} figures "
      "in {:.0f} s\n",
      o.out, o.out, o.out, o.out, figure_files.size(), results.seconds);
  std::cout << fmt::format(
      "{} claims, {} of them not reproduced or contradicted (see the summary of the report)\n",
      results.claims.size(), validation::count_not_reproduced(results));
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
  cmd->add_option("--threads", o->threads, "worker threads (0: all cores)")
      ->transform(integer_in(0, 1024));
  cmd->add_flag("!--no-figures", o->figures, "skip rendering");
  cmd->add_flag("--quiet", o->quiet, "no progress on stderr (notes and errors still)");
  cmd->add_flag("--relax-each-run", o->relax_each_run,
                "relax every run itself instead of restoring the relaxed state of an earlier run "
                "with the same N, density and seed (the same results, more CPU)");
  set_callback_with_config(cmd, [o] { run_reproduce(*o); });
}

}  // namespace molchaos::app
