// The impact-parameter figure: the histogram of s = (1 − (ĝ·e)²)^((d−1)/2) of the colliding
// pairs as its departure from flat, fraction·bins − 1 (zero under molecular chaos), original gas
// against the flux-shuffled gas, one curve per ε, one panel per dimension and density.
#include <algorithm>
#include <set>
#include <string>
#include <utility>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {

RenderedFigure render_impact_parameter(const std::vector<validation::ImpactParameterRow>& rows,
                                       const RenderOptions& options) {
  const auto panels = detail::state_panels(rows);
  std::set<double> restitutions;
  for (const auto& r : rows) restitutions.insert(r.restitution);
  detail::FigureScript script;
  script.basename = "fig_impact_parameter";
  script.description =
      "Impact parameter s = (1 - (g.e/|g|)^2)^((d-1)/2) of the colliding pairs: the fraction of\n"
      "collisions per bin of s over its molecular-chaos value 1/bins, minus 1 (mean over runs).\n"
      "Blocks: bin centre of s, fraction*bins - 1, error.";
  const std::size_t n_panels = panels.size();
  script.canvas = detail::row_of_panels(n_panels, 820, 3.7);  // taller: room for the key
  std::string& c = script.commands;
  c += "  set multiplot layout 1," + std::to_string(n_panels) +
       " title 'impact parameter: departure from flat (molecular chaos = 0); filled, solid: "
       "original gas; open, dashed: flux shuffle'\n";
  c += "  set xlabel 's (0 head-on, 1 grazing)'\n  set ylabel 'fraction · bins − 1'\n";
  c += "  set xrange [0:1]\n  set key top left font font_small box opaque maxrows 6\n";
  c += detail::k_light_grid_small_bars;
  std::size_t p = 0;
  for (const auto& [d, n] : panels) {
    std::string plot = "  plot 0 with lines linecolor rgb 'black' dashtype 2 notitle";
    std::size_t s = 0, k = 0;
    for (const double eps : restitutions) {
      for (const std::string mode : {"none", "flux"}) {
        detail::Rows data;
        for (const auto& r : rows)
          if (r.dimension == d && r.density == n && r.restitution == eps && r.mode == mode) {
            const double bins = 1.0 / (r.s_hi - r.s_lo);
            data.push_back(
                {0.5 * (r.s_lo + r.s_hi), r.fraction.value * bins - 1.0, r.fraction.error * bins});
          }
        if (data.empty()) continue;
        // One key entry per ε (the original gas's curve); the line styles tell the gases apart.
        detail::add_series(script, plot, detail::panel_block_name(p, s++), std::move(data),
                           mode == "none" ? "yerrorlines pointtype 7 pointsize 0.6 dashtype 1"
                                          : "yerrorlines pointtype 6 pointsize 0.6 dashtype 2",
                           k, mode == "none" ? "ε = " + detail::label_number(eps) : "");
      }
      ++k;
    }
    c += "  set title " + detail::quote(detail::dimension_density_title(d, n)) +
         "\n  set autoscale y\n" + plot + "\n";
    ++p;
  }
  return detail::render(script, options);
}

}  // namespace molchaos::figures
