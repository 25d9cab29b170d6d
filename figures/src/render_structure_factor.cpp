// Structure-factor figure of the break-down: (left) S⊥(k, τ) of the largest shear modes in boxes
// above and below L_c against linear hydrodynamics (no free parameter); (middle, right) S⊥ and
// the density S(k) of the largest modes against ln t for the original and the randomized gases.
#include <cmath>
#include <string>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {
namespace {

void linear_theory_panel(detail::FigureScript& script,
                         const std::vector<validation::StructureFactorCurve>& curves,
                         const std::string& title_prefix = "") {
  std::string& c = script.commands;
  c += "  set logscale y\n  set xlabel 'collisions per particle τ'\n"
       "  set ylabel 'S_{⊥}(k, τ)'\n  set key top left font font_small box opaque\n"
       "  set title " +
       detail::quote(title_prefix + "linear hydrodynamics (lines) against simulation (points)") +
       "\n";
  std::string plot = "  plot 1 with lines linecolor rgb 'black' dashtype 2 notitle";
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const auto& k = curves[i];
    detail::require_same_size("StructureFactorCurve.measured", k.measured.size(), "tau",
                              k.tau.size());
    detail::require_same_size("StructureFactorCurve.error", k.error.size(), "tau", k.tau.size());
    detail::require_same_size("StructureFactorCurve.predicted", k.predicted.size(), "tau",
                              k.tau.size());
    detail::Rows rows;
    for (std::size_t j = 0; j < k.tau.size(); ++j)
      rows.push_back({k.tau[j], k.measured[j], k.error[j], k.predicted[j]});
    const std::string block = detail::block_name("sperp", i);
    script.data.emplace_back(block, rows);
    const std::string label = "L = " + detail::label_number(std::round(k.box)) + "σ, kσ = " +
                              detail::label_number(std::round(k.wavenumber * 1e4) / 1e4);
    detail::add_plot_element(plot, "$" + block +
                                       " using 1:2:3 with yerrorbars pointtype 7 pointsize 0.6 "
                                       "linecolor rgb " +
                                       detail::colour(i + 1) + " title " + detail::quote(label));
    detail::add_plot_element(plot, "$" + block + " using 1:4 with lines linecolor rgb " +
                                       detail::colour(i + 1) + " notitle");
  }
  c += plot + "\n  unset logscale y\n";
}

void gases_panel(detail::FigureScript& script, const validation::GasFieldStudy& study,
                 bool density) {
  std::string& c = script.commands;
  c += "  set xlabel 'ln t'\n  set key top left font font_small box opaque\n";
  if (density) {
    c += "  set ylabel 'S(k) of the largest modes'\n  set title 'density'\n";
  } else {
    c += "  set logscale y\n  set ylabel 'S_{⊥}(k) of the largest modes'\n"
         "  set title 'shear modes (vortices)'\n";
  }
  std::string plot = "  plot 1 with lines linecolor rgb 'black' dashtype 2 notitle";
  for (std::size_t i = 0; i < study.series.size(); ++i) {
    const auto& g = study.series[i];
    detail::Rows rows;
    for (const auto& p : g.points) {
      const auto& m = density ? p.density : p.transverse;
      rows.push_back({p.log_time, m.value, m.error, p.transverse_predicted});
    }
    const std::string block = detail::block_name(density ? "dens" : "gas", i);
    script.data.emplace_back(block, rows);
    const std::string label = g.mode == "none"    ? "original gas"
                              : g.mode == "paper" ? "paper's shuffle"
                                                  : "flux shuffle";
    detail::add_plot_element(plot, "$" + block +
                                       " using 1:2:3 with yerrorlines pointtype 7 pointsize 0.6 "
                                       "linecolor rgb " +
                                       detail::colour(detail::gas_colour_index(g.mode, i)) +
                                       " title " + detail::quote(label));
    if (!density && g.mode == "none")
      detail::add_plot_element(plot, "$" + block +
                                         " using 1:4 with lines dashtype 3 linewidth 2 "
                                         "linecolor rgb " +
                                         detail::colour(detail::gas_colour_index(g.mode, i)) +
                                         " title 'original gas, linear hydrodynamics'");
  }
  c += plot + "\n  unset logscale y\n";
}

}  // namespace

RenderedFigure render_structure_factors(const std::vector<validation::StructureFactorCurve>& curves,
                                        const validation::GasFieldStudy& gases,
                                        const RenderOptions& options) {
  detail::require_non_empty("curves", curves.size());
  detail::require_non_empty("gases.series", gases.series.size());
  detail::FigureScript script;
  script.basename = "fig_structure_factor";
  script.description =
      "Velocity and density structure factors through the break-down of the HCS (d = 2).\n"
      "sperp blocks: tau, S_perp (run mean), standard error, linear prediction.\n"
      "gas/dens blocks: ln t, S_perp or S (mean over the shells |m|^2 <= 2), standard error,\n"
      "S_perp by linear hydrodynamics (1 for the shuffled gases).";
  script.canvas.png_width = 2100;
  script.canvas.png_height = 700;
  script.canvas.pdf_width = 10.5;
  script.canvas.pdf_height = 3.5;
  std::string& c = script.commands;
  c += "  set multiplot layout 1,3 title " +
       detail::quote("d = 2, n = " + detail::label_number(gases.spec.density) +
                     ", ε = " + detail::label_number(gases.spec.restitution)) +
       "\n";
  c += detail::k_light_grid_small_bars;
  linear_theory_panel(script, curves);
  gases_panel(script, gases, false);
  gases_panel(script, gases, true);
  c += "  unset multiplot\n";
  return detail::render(script, options);
}

RenderedFigure render_linear_hydrodynamics(
    const std::vector<validation::StructureFactorCurve>& curves, const std::string& title,
    const std::string& basename, const RenderOptions& options) {
  detail::require_non_empty("curves", curves.size());
  detail::FigureScript script;
  script.basename = basename;
  script.description =
      "S_perp(k, tau) of the largest shear modes in boxes above and below L_c against linear\n"
      "hydrodynamics (no free parameter). sperp blocks: tau, S_perp (run mean), standard error,\n"
      "linear prediction.";
  script.canvas.png_width = 1000;
  script.canvas.png_height = 760;
  script.canvas.pdf_width = 5.0;
  script.canvas.pdf_height = 3.8;
  script.commands += detail::k_light_grid_small_bars;
  linear_theory_panel(script, curves, title + ": ");
  return detail::render(script, options);
}

}  // namespace molchaos::figures
