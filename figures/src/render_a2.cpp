// a2(ε), the second Sonine coefficient of the homogeneous cooling state, one panel per density:
// the MD gases and DSMC (points, mean ± standard error over runs) against the first-Sonine a2 the
// paper quotes (van Noije & Ernst, Eq. (25); dashed) and the improved a2 with a2² and a3 (solid).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {
namespace {

// Checks one panel's sizes and returns its ε range over the points.
std::pair<double, double> checked_epsilon_range(const validation::A2Panel& panel,
                                                const std::string& field) {
  detail::require_non_empty(field + ".series", panel.series.size());
  detail::require_same_size(field + ".first_sonine", panel.first_sonine.size(),
                            field + ".theory_restitution", panel.theory_restitution.size());
  detail::require_same_size(field + ".improved", panel.improved.size(),
                            field + ".theory_restitution", panel.theory_restitution.size());
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t s = 0; s < panel.series.size(); ++s) {
    const auto& series = panel.series[s];
    const std::string series_field = field + ".series[" + std::to_string(s) + "]";
    detail::require_non_empty(series_field + ".restitution", series.restitution.size());
    detail::require_same_size(series_field + ".a2", series.a2.size(), series_field + ".restitution",
                              series.restitution.size());
    lo = std::min(lo, *std::min_element(series.restitution.begin(), series.restitution.end()));
    hi = std::max(hi, *std::max_element(series.restitution.begin(), series.restitution.end()));
  }
  return {lo, hi};
}

}  // namespace

RenderedFigure render_a2(const validation::A2Data& data, const RenderOptions& options) {
  detail::require_non_empty("A2Data.panels", data.panels.size());
  detail::FigureScript script;
  script.basename = "fig_a2_of_eps";
  script.description =
      "a2(eps), the second Sonine coefficient of the homogeneous cooling state, one panel per\n"
      "density. Data blocks pP_sS: eps, a2 (mean over runs of the window average), its standard\n"
      "error, eps as drawn (series shifted sideways by a few thousandths so that their error bars\n"
      "do not hide one another); pP_theory: eps, first-Sonine a2 (van Noije & Ernst), improved\n"
      "a2 (with a2^2 and a3).";
  const auto panels = data.panels.size();
  detail::begin_epsilon_panels(script, panels, data.title, "a_2", "bottom right");
  std::string& c = script.commands;
  for (std::size_t p = 0; p < panels; ++p) {
    const auto& panel = data.panels[p];
    const std::string prefix = "p" + std::to_string(p);
    const auto [eps_min, eps_max] =
        checked_epsilon_range(panel, "A2Data.panels[" + std::to_string(p) + "]");
    std::string plot;
    if (!panel.theory_restitution.empty()) {
      detail::Rows theory;
      for (std::size_t i = 0; i < panel.theory_restitution.size(); ++i)
        theory.push_back(
            {panel.theory_restitution[i], panel.first_sonine[i].value, panel.improved[i].value});
      const std::string block = "$" + prefix + "_theory";
      script.data.emplace_back(prefix + "_theory", theory);
      detail::add_plot_element(plot, block +
                                         " using 1:2 with lines linecolor rgb 'black' dashtype "
                                         "(8,5) linewidth 1.2 title 'first Sonine (Eq. (25))'");
      detail::add_plot_element(plot, block +
                                         " using 1:3 with lines linecolor rgb 'black' linewidth "
                                         "1.2 title 'with a_2^2 and a_3'");
    }
    const auto count = panel.series.size();
    for (std::size_t s = 0; s < count; ++s) {
      const auto& series = panel.series[s];
      const double shift = detail::sideways_shift(s, count, eps_min, eps_max);
      detail::Rows rows;
      for (std::size_t i = 0; i < series.restitution.size(); ++i)
        rows.push_back({series.restitution[i], series.a2[i].value, std::abs(series.a2[i].error),
                        series.restitution[i] + shift});
      const std::string block = prefix + "_s" + std::to_string(s);
      script.data.emplace_back(block, rows);
      detail::add_plot_element(
          plot, "$" + block + " using 4:2:3 " + detail::gas_points(series.mode, s, series.label));
    }
    detail::set_density_panel(c, panel.density, eps_min, eps_max);
    // Room below the data for the key.
    c += "  set autoscale y\n  set offsets 0, 0, graph 0.05, graph 0.45\n";
    c += plot + "\n";
  }
  return detail::render(script, options);
}

}  // namespace molchaos::figures
