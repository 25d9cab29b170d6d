// The impact-parameter figure: the histogram of s = (1 − (ĝ·e)²)^((d−1)/2) of the colliding
// pairs as its departure from flat, fraction·bins − 1 (zero under molecular chaos), original gas
// against the flux-shuffled gas, one panel per dimension and density. Each bin is the
// inverse-variance mean over the panel's restitutions: ten curves of one panel lay over each
// other within their errors, and the mean shows the shape they share (the table holds each ε).
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {

RenderedFigure render_impact_parameter(const std::vector<validation::ImpactParameterRow>& rows,
                                       const RenderOptions& options) {
  const auto panels = detail::state_panels(rows);
  detail::FigureScript script;
  script.basename = "fig_impact_parameter";
  script.description =
      "Impact parameter s = (1 - (g.e/|g|)^2)^((d-1)/2) of the colliding pairs: the fraction of\n"
      "collisions per bin of s over its molecular-chaos value 1/bins, minus 1, inverse-variance\n"
      "mean over the restitutions of the panel. Blocks: bin centre of s, fraction*bins - 1, error.";
  const std::size_t n_panels = panels.size();
  script.canvas = detail::row_of_panels(n_panels, 820, 3.7);
  std::string& c = script.commands;
  c += "  set multiplot layout 1," + std::to_string(n_panels) +
       " title 'impact parameter: departure from flat (molecular chaos = 0), mean over ε'\n";
  c += "  set xlabel 's (0 head-on, 1 grazing)'\n  set ylabel 'fraction · bins − 1'\n";
  c += "  set xrange [0:1]\n  set key top left font font_small box opaque\n";
  c += detail::k_light_grid_small_bars;
  std::size_t p = 0;
  for (const auto& [d, n] : panels) {
    std::string plot = "  plot 0 with lines linecolor rgb 'black' dashtype 2 notitle";
    std::size_t s = 0, k = 0;
    for (const std::string mode : {"none", "flux"}) {
      // Per bin centre: the sums of w·y and of w = 1/error² over the restitutions.
      std::map<double, std::pair<double, double>> sums;
      std::set<double> restitutions;
      for (const auto& r : rows) {
        if (r.dimension != d || r.density != n || r.mode != mode || !(r.fraction.error > 0.0))
          continue;
        const double bins = 1.0 / (r.s_hi - r.s_lo);
        const double error = r.fraction.error * bins, w = 1.0 / (error * error);
        auto& [wy, wsum] = sums[0.5 * (r.s_lo + r.s_hi)];
        wy += w * (r.fraction.value * bins - 1.0);
        wsum += w;
        restitutions.insert(r.restitution);
      }
      detail::Rows data;
      for (const auto& [centre, sum] : sums)
        data.push_back({centre, sum.first / sum.second, 1.0 / std::sqrt(sum.second)});
      if (data.empty()) continue;
      detail::add_series(script, plot, detail::panel_block_name(p, s++), std::move(data),
                         mode == "none" ? "yerrorlines pointtype 7 pointsize 0.8 dashtype 1"
                                        : "yerrorlines pointtype 6 pointsize 0.8 dashtype 2",
                         detail::gas_colour_index(mode, k++),
                         (mode == "none" ? "original gas" : "flux shuffle") + std::string(", ") +
                             std::to_string(restitutions.size()) + " ε");
    }
    c += "  set title " + detail::quote(detail::dimension_density_title(d, n)) +
         "\n  set autoscale y\n" + plot + "\n";
    ++p;
  }
  return detail::render(script, options);
}

}  // namespace molchaos::figures
