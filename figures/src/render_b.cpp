// b(ε), the velocity-correlation coefficient of Eq. (18), one panel per density: inferred from A
// as the paper does (Eq. 29) and measured from the contact statistics. b = 0 is molecular chaos.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {

RenderedFigure render_b(const validation::BData& data, const RenderOptions& options) {
  detail::require_non_empty("BData.panels", data.panels.size());
  detail::FigureScript script;
  script.basename = "fig_b_of_eps";
  script.description =
      "b(eps), the velocity-correlation coefficient (b = 0: molecular chaos), one panel per\n"
      "density. Data blocks pP_sS: eps, b, standard error of b, eps as drawn (series are shifted\n"
      "sideways by a few thousandths so that their error bars do not hide one another).";
  const auto panels = data.panels.size();
  detail::begin_epsilon_panels(script, panels, data.title, "b", "top right");
  std::string& c = script.commands;

  constexpr std::array<const char*, 5> k_point_types{"7", "5", "9", "4", "13"};
  for (std::size_t p = 0; p < panels; ++p) {
    const auto& panel = data.panels[p];
    const std::string field = "BData.panels[" + std::to_string(p) + "]";
    detail::require_non_empty(field + ".series", panel.series.size());
    double eps_min = std::numeric_limits<double>::infinity(), eps_max = -eps_min;
    std::size_t points = 0;
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const auto& series = panel.series[s];
      const std::string series_field = field + ".series[" + std::to_string(s) + "]";
      detail::require_same_size(series_field + ".b", series.b.size(), series_field + ".restitution",
                                series.restitution.size());
      points += series.restitution.size();
      for (double eps : series.restitution) {
        eps_min = std::min(eps_min, eps);
        eps_max = std::max(eps_max, eps);
      }
    }
    // A series may have no point (b at contact needs the standard error of the mean dyad, which
    // one run per point does not give): it is left out of the plot; a panel needs one point.
    detail::require_non_empty(field + ".series[*].restitution", points);
    std::string plot =
        "  plot 0 with lines linecolor rgb 'black' dashtype (8,5) linewidth 1 "
        "title 'molecular chaos (b = 0)'";
    const auto count = panel.series.size();
    for (std::size_t s = 0; s < count; ++s) {
      const auto& series = panel.series[s];
      if (series.restitution.empty()) continue;
      const double shift = detail::sideways_shift(s, count, eps_min, eps_max);
      detail::Rows rows;
      for (std::size_t i = 0; i < series.restitution.size(); ++i) {
        rows.push_back({series.restitution[i], series.b[i].value, std::abs(series.b[i].error),
                        series.restitution[i] + shift});
      }
      const std::string block = "p" + std::to_string(p) + "_s" + std::to_string(s);
      script.data.emplace_back(block, rows);
      plot += ", \\\n       $" + block + " using 4:2:3 with yerrorbars pointtype " +
              k_point_types[s % k_point_types.size()] +
              " pointsize 1.3*point_scale linewidth 1 linecolor rgb " + detail::colour(s + 1) +
              " title " + detail::quote(series.label);
    }
    detail::set_density_panel(c, panel.density, eps_min, eps_max);
    c += "  set autoscale y\n  set offsets 0, 0, graph 0.5, graph 0.05\n";
    c += plot + "\n";
  }
  return detail::render(script, options);
}

}  // namespace molchaos::figures
