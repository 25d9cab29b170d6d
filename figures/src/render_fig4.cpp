// Fig. 4 of the paper: A(ε) = τ0(1 − ε²) against ε, one panel per density; the randomized gas
// (squares) stays flat, the original gas (triangles) depends on ε through b(ε) (Eq. 29); the
// lines are least-squares fits, the dashed line kinetic theory without correlations.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {

RenderedFigure render_fig4(const validation::Fig4Data& data, const RenderOptions& options) {
  detail::require_non_empty("Fig4Data.panels", data.panels.size());
  detail::FigureScript script;
  script.basename = "fig4_A_of_eps";
  script.description =
      "Fig. 4 of Poeschel, Brilliantov, Schwager: A(eps) = tau0 (1 - eps^2) against eps, one "
      "panel\n"
      "per density. Data blocks pP_sS: eps, A, standard error of A; pP_fitS: the fitted line at\n"
      "the ends of its eps range; pP_theory: kinetic theory A(eps) with b = 0.";
  const auto panels = data.panels.size();
  detail::begin_epsilon_panels(script, panels, data.title, "A  [σ√(m/T_0)]", "top left");
  std::string& c = script.commands;

  for (std::size_t p = 0; p < panels; ++p) {
    const auto& panel = data.panels[p];
    const std::string field = "Fig4Data.panels[" + std::to_string(p) + "]";
    detail::require_non_empty(field + ".series", panel.series.size());
    detail::require_same_size(field + ".theory_A", panel.theory_A.size(),
                              field + ".theory_restitution", panel.theory_restitution.size());
    const std::string prefix = "p" + std::to_string(p);
    double eps_min = std::numeric_limits<double>::infinity();
    double eps_max = -eps_min;
    std::vector<std::string> elements;
    bool any_fit = false;
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const auto& series = panel.series[s];
      const std::string series_field = field + ".series[" + std::to_string(s) + "]";
      detail::require_non_empty(series_field + ".points", series.points.size());
      detail::Rows rows;
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const auto& point : series.points) {
        rows.push_back({point.restitution, point.A.value, std::abs(point.A.error)});
        lo = std::min(lo, point.restitution);
        hi = std::max(hi, point.restitution);
      }
      eps_min = std::min(eps_min, lo);
      eps_max = std::max(eps_max, hi);
      const std::string block = prefix + "_s" + std::to_string(s);
      script.data.emplace_back(block, rows);
      const std::string colour =
          "linecolor rgb " + detail::colour(detail::gas_colour_index(series.mode, s));
      if (series.fit) {
        // The fitted line spans the series' own ε range, as in the paper.
        const auto& fit = *series.fit;
        const std::string fit_block = prefix + "_fit" + std::to_string(s);
        script.data.emplace_back(fit_block, detail::Rows{{lo, fit.intercept + fit.slope * lo},
                                                         {hi, fit.intercept + fit.slope * hi}});
        c += "  # " + series.label + ": A = (" + detail::number(fit.intercept) + " ± " +
             detail::number(fit.intercept_error) + ") + (" + detail::number(fit.slope) + " ± " +
             detail::number(fit.slope_error) +
             ") eps, chi2/dof = " + detail::number(fit.chi2_per_dof) + "\n";
        elements.push_back("$" + fit_block + " using 1:2 with lines " + colour +
                           " linewidth 1 notitle");
        any_fit = true;
      }
      elements.push_back("$" + block + " using 1:2:3 " +
                         detail::gas_points(series.mode, s, series.label));
    }
    if (!panel.theory_A.empty()) {
      detail::Rows theory;
      for (std::size_t i = 0; i < panel.theory_A.size(); ++i) {
        theory.push_back({panel.theory_restitution[i], panel.theory_A[i]});
      }
      script.data.emplace_back(prefix + "_theory", theory);
      elements.push_back("$" + prefix +
                         "_theory using 1:2 with lines linecolor rgb 'black' dashtype (8,5) "
                         "linewidth 1.2 title 'kinetic theory (b = 0)'");
    }
    if (any_fit) {
      elements.push_back(
          "keyentry with lines linecolor rgb '#555555' linewidth 1 title 'least-squares fits'");
    }
    detail::set_density_panel(c, panel.density, eps_min, eps_max);
    // Room above the data for the key (six entries: at graph 0.35 it hid the tops of the
    // highest bars).
    c += "  set autoscale y\n  set offsets 0, 0, graph 0.5, graph 0.05\n";
    std::string plot;
    for (const auto& element : elements) detail::add_plot_element(plot, element);
    c += plot + "\n";
  }
  return detail::render(script, options);
}

}  // namespace molchaos::figures
