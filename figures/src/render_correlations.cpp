// The correlation study's figures: pair velocity correlations G∥(r), G⊥(r) of the original and
// the molecular-chaos gas at three times; the contact moments against ε; the cooling rate taken
// apart into collision frequency and energy loss per collision against ε.
#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {
namespace {

std::string gas_label(const std::string& mode) {
  if (mode == "none") return "original";
  return mode == "dsmc" ? "molecular chaos (DSMC)" : "molecular chaos (flux)";
}

using detail::add_series;

// The ε axis of the panel of state (d, n): the restitutions of its rows.
template <class Row>
void set_panel_epsilon_axis(std::string& commands, const std::vector<Row>& rows, int d, double n) {
  double lo = 1.0, hi = 0.0;
  for (const Row& r : rows)
    if (r.dimension == d && r.density == n) {
      lo = std::min(lo, r.restitution);
      hi = std::max(hi, r.restitution);
    }
  detail::set_epsilon_axis(commands, lo, hi);
}

}  // namespace

RenderedFigure render_pair_correlations(const std::vector<validation::PairCorrelationRow>& rows,
                                        int dimension, double density, double restitution,
                                        const RenderOptions& options) {
  std::set<std::tuple<std::string, double>> sets;  // (mode, τ)
  for (const auto& r : rows)
    if (r.dimension == dimension && r.density == density && r.restitution == restitution &&
        r.side == "all")
      sets.emplace(r.mode, r.tau);
  detail::require_non_empty("rows (of the requested state point)", sets.size());
  detail::FigureScript script;
  script.basename = "fig_pair_correlations";
  script.description =
      "Velocity correlations of pairs at separation r: G_par = <(c1.r)(c2.r)>, G_perp =\n"
      "<c1.c2 - (c1.r)(c2.r)>/(d - 1), c = v/sqrt(2T). Blocks: r (bin centre), G, error.";
  script.canvas.png_width = 1600;
  script.canvas.png_height = 760;
  script.canvas.pdf_width = 7.2;
  script.canvas.pdf_height = 3.4;
  std::string& c = script.commands;
  c += "  set multiplot layout 1,2 title " +
       detail::quote(detail::dimension_density_title(dimension, density) +
                     ", ε = " + detail::label_number(restitution)) +
       "\n";
  c += "  set logscale x\n  set xlabel 'r/σ'\n  set key top right font font_small box opaque\n";
  c += detail::k_light_grid_small_bars;
  for (int which = 0; which < 2; ++which) {
    c += std::string("  set ylabel ") + (which == 0 ? "'G_{∥}(r)'" : "'G_{⊥}(r)'") + "\n";
    std::string plot = "  plot 0 with lines linecolor rgb 'black' dashtype 2 notitle";
    std::size_t k = 0, time_index = 0;
    std::string previous_mode;
    for (const auto& [mode, tau] : sets) {
      if (mode != previous_mode) time_index = 0;
      previous_mode = mode;
      detail::Rows data;
      for (const auto& r : rows)
        if (r.dimension == dimension && r.density == density && r.restitution == restitution &&
            r.side == "all" && r.mode == mode && r.tau == tau) {
          const auto& g = which == 0 ? r.G_par : r.G_perp;
          data.push_back({std::sqrt(r.r_lo * r.r_hi), g.value, g.error});
        }
      const std::string style = std::string("yerrorlines pointtype ") +
                                (mode == "none" ? "7" : "6") + " pointsize 0.8 dashtype " +
                                (mode == "none" ? "1" : "2");
      add_series(script, plot, detail::panel_block_name(static_cast<std::size_t>(which), k), data,
                 style, time_index + 1,
                 gas_label(mode) + ", τ = " + detail::label_number(std::round(tau)));
      ++k;
      ++time_index;
    }
    c += plot + "\n";
  }
  return detail::render(script, options);
}

RenderedFigure render_contact_moments(const std::vector<validation::ContactMomentRow>& rows,
                                      const RenderOptions& options) {
  const auto panels = detail::state_panels(rows);
  detail::FigureScript script;
  script.basename = "fig_contact_moments";
  script.description =
      "Collision averages of pre-collision velocities, c = v/sqrt(2T): <(c1.e)(c2.e)> and\n"
      "<c1.c2>; molecular chaos gives -1/4 + a2/16 for both. Blocks: eps, value, error.";
  detail::begin_epsilon_panels(script, panels.size(), "contact moments", "collision average",
                               "bottom right");
  std::size_t p = 0;
  for (const auto& [d, n] : panels) {
    std::string plot =
        "  plot -0.25 with lines linecolor rgb 'black' dashtype 2 title "
        "'molecular chaos, a_2 = 0'";
    std::size_t s = 0;
    const std::array<std::string, 3> modes{"none", "flux", "dsmc"};
    for (std::size_t k = 0; k < modes.size(); ++k)
      for (int which = 0; which < 2; ++which) {
        detail::Rows data;
        const double shift = (static_cast<double>(2 * k) + which - 2.5) * 0.0012;
        for (const auto& r : rows)
          if (r.dimension == d && r.density == n && r.mode == modes[k]) {
            const auto& m = which == 0 ? r.c1e_c2e : r.c1_dot_c2;
            data.push_back({r.restitution + shift, m.value, m.error});
          }
        if (data.empty()) continue;  // a gas not run in this panel (DSMC in a quick look)
        add_series(script, plot, detail::panel_block_name(p, s), data,
                   "yerrorbars pointtype " + detail::gas_point_type(modes[k], k),
                   static_cast<std::size_t>(which) + 1,
                   std::string(which == 0 ? "<(c_1·e)(c_2·e)>" : "<c_1·c_2>") + ", " +
                       gas_label(modes[k]));
        ++s;
      }
    // Room below the data for the key (seven entries).
    script.commands += "  set title " + detail::quote(detail::dimension_density_title(d, n)) + "\n";
    set_panel_epsilon_axis(script.commands, rows, d, n);
    script.commands +=
        "  set autoscale y\n  set offsets 0, 0, graph 0.05, graph 1.1\n" + plot + "\n";
    ++p;
  }
  return detail::render(script, options);
}

RenderedFigure render_cooling_decomposition(
    const std::vector<validation::CoolingDecompositionRow>& rows, const RenderOptions& options) {
  const auto panels = detail::state_panels(rows);
  detail::FigureScript script;
  script.basename = "fig_cooling_decomposition";
  script.description =
      "The cooling rate taken apart, original gas against molecular chaos (paired by seed):\n"
      "ln(A_orig/A_chaos) fitted, and its two factors ln(omega_chaos/omega_orig) (collision\n"
      "frequency) and ln(Y_chaos/Y_orig) (energy loss per collision). Blocks: eps, value, error.";
  detail::begin_epsilon_panels(script, panels.size(), "cooling rate taken apart", "logarithm",
                               "top right");
  std::size_t p = 0;
  for (const auto& [d, n] : panels) {
    std::string plot = "  plot 0 with lines linecolor rgb 'black' dashtype 2 notitle";
    for (int which = 0; which < 3; ++which) {
      detail::Rows data;
      for (const auto& r : rows)
        if (r.dimension == d && r.density == n) {
          const auto m = which == 0   ? validation::Measurement{std::log(r.A_ratio.value),
                                                              r.A_ratio.error / r.A_ratio.value}
                         : which == 1 ? r.log_frequency
                                      : r.log_dissipation;
          data.push_back({r.restitution + (which - 1) * 0.002, m.value, m.error});
        }
      const char* titles[] = {"ln(A_{orig}/A_{chaos}), Haff fit",
                              "ln(ω_{chaos}/ω_{orig}), collision frequency",
                              "ln(Y_{chaos}/Y_{orig}), energy loss per collision"};
      add_series(script, plot, detail::panel_block_name(p, static_cast<std::size_t>(which)), data,
                 std::string("yerrorbars pointtype ") + (which == 0   ? "7"
                                                         : which == 1 ? "5"
                                                                      : "9"),
                 static_cast<std::size_t>(which) + 1, titles[which]);
    }
    // Room above the data for the key (three entries).
    script.commands += "  set title " + detail::quote(detail::dimension_density_title(d, n)) + "\n";
    set_panel_epsilon_axis(script.commands, rows, d, n);
    script.commands +=
        "  set autoscale y\n  set offsets 0, 0, graph 0.45, graph 0.05\n" + plot + "\n";
    ++p;
  }
  return detail::render(script, options);
}

}  // namespace molchaos::figures
