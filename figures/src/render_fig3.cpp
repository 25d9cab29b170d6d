// Fig. 3 of the paper: the temperature T(t)/T0 of the original and the randomized gas against
// ln t, with Haff's law (Eq. 2) dashed, the clustering onset marked, and an inset magnifying
// 2.5 ≤ ln t ≤ 3 where the paper sees a small systematic deviation. A lower panel shows what the
// log axis hides: each gas's relative deviation T/T_Haff − 1 (in %) with its error band.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {
namespace {

// Below this many points a curve is drawn with error bars; above, with a shaded error band.
constexpr std::size_t k_max_points_for_error_bars = 40;

// Dash patterns of the Haff's-law lines, one per line, so that lines lying on top of each other
// (in the inset they differ by less than a line width) stay apart.
const char* const k_theory_dashes[] = {"(10,6)", "(3,5)", "(14,5,3,5)"};
// Point types of the simulated gases (drawn every few samples) for the same reason.
const int k_gas_points[] = {7, 5, 9, 11, 13};

struct CurveRows {
  detail::Rows rows;  // ln t, T, T − err, T + err
  bool has_error = false;
};

CurveRows curve_rows(const validation::TemperatureCurve& curve, const std::string& field) {
  detail::require_non_empty(field + ".t", curve.t.size());
  detail::require_same_size(field + ".T", curve.T.size(), field + ".t", curve.t.size());
  if (!curve.T_error.empty()) {
    detail::require_same_size(field + ".T_error", curve.T_error.size(), field + ".t",
                              curve.t.size());
  }
  CurveRows out;
  for (std::size_t i = 0; i < curve.t.size(); ++i) {
    // ln t is undefined at t = 0, where series conventionally start: such samples are skipped.
    if (!(curve.t[i] > 0.0)) continue;
    if (!(curve.T[i] > 0.0) || !std::isfinite(curve.T[i])) {
      throw std::invalid_argument(field + ".T[" + std::to_string(i) +
                                  "] is not a positive number (log axis)");
    }
    const double error = curve.T_error.empty() ? 0.0 : std::abs(curve.T_error[i]);
    out.has_error = out.has_error || error > 0.0;
    // The band is clipped at T/10 so that it stays on the log axis.
    out.rows.push_back({std::log(curve.t[i]), curve.T[i],
                        std::max(curve.T[i] - error, 0.1 * curve.T[i]), curve.T[i] + error});
  }
  if (out.rows.empty()) throw std::invalid_argument(field + ".t has no entry t > 0");
  return out;
}

// Deviation rows in per cent: ln t, 100·d, 100·(d − err), 100·(d + err).
detail::Rows deviation_rows(const validation::TemperatureCurve& curve, const std::string& field) {
  detail::require_same_size(field + ".T", curve.T.size(), field + ".t", curve.t.size());
  detail::require_same_size(field + ".T_error", curve.T_error.size(), field + ".t", curve.t.size());
  detail::Rows rows;
  for (std::size_t i = 0; i < curve.t.size(); ++i) {
    if (!(curve.t[i] > 0.0) || !std::isfinite(curve.T[i])) continue;
    const double d = 100.0 * curve.T[i], e = 100.0 * std::abs(curve.T_error[i]);
    rows.push_back({std::log(curve.t[i]), d, d - e, d + e});
  }
  return rows;
}

// Colour of curve i: a gas takes its colour of every other figure (detail::gas_colour_index), a
// theory line the next free ones in turn; colour 0 (black) stays for the zero lines.
std::size_t curve_colour(const validation::Fig3Data& data, std::size_t i) {
  if (!data.curves[i].is_theory) return detail::gas_colour_index(data.curves[i].mode, i);
  std::size_t theory = 0;
  for (std::size_t j = 0; j < i; ++j) theory += data.curves[j].is_theory ? 1 : 0;
  return detail::gas_colour_index("", theory);
}

// Colour of a deviation curve: that of the gas whose label it starts with.
std::size_t deviation_colour(const validation::Fig3Data& data, const std::string& label) {
  for (std::size_t i = 0; i < data.curves.size(); ++i)
    if (!data.curves[i].is_theory && label.starts_with(data.curves[i].label))
      return curve_colour(data, i);
  return 0;
}

// The plot command of the upper panel (and, without titles, of the inset).
std::string temperature_plot(const validation::Fig3Data& data, const std::vector<CurveRows>& curves,
                             bool with_titles, const std::string& axes) {
  std::string plot;
  for (std::size_t i = 0; i < curves.size(); ++i)
    if (curves[i].has_error && curves[i].rows.size() > k_max_points_for_error_bars)
      detail::add_plot_element(plot, "$curve" + std::to_string(i) +
                                         " using 1:3:4 with filledcurves fillstyle transparent "
                                         "solid 0.25 noborder linecolor rgb " +
                                         detail::colour(curve_colour(data, i)) + axes + " notitle");
  std::size_t theory_count = 0, gas_count = 0;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i = 0; i < curves.size(); ++i) {
      const auto& curve = data.curves[i];
      if (curve.is_theory != (pass == 1)) continue;
      const std::string block = "$curve" + std::to_string(i);
      const std::string title =
          with_titles && !curve.label.empty() ? "title " + detail::quote(curve.label) : "notitle";
      const std::string colour = "linecolor rgb " + detail::colour(curve_colour(data, i));
      if (curve.is_theory) {
        const std::string dash = k_theory_dashes[theory_count++ % std::size(k_theory_dashes)];
        detail::add_plot_element(plot, block + " using 1:2 with lines " + colour + " dashtype " +
                                           dash + " linewidth 1.6" + axes + " " + title);
      } else if (curves[i].has_error && curves[i].rows.size() <= k_max_points_for_error_bars) {
        detail::add_plot_element(plot, block + " using 1:2:3:4 with yerrorlines pointtype 7 " +
                                           "pointsize 0.8*point_scale " + colour + axes + " " +
                                           title);
      } else {
        const int points = k_gas_points[gas_count++ % std::size(k_gas_points)];
        detail::add_plot_element(
            plot, block + " using 1:2 with linespoints pointtype " + std::to_string(points) +
                      " pointinterval 6 pointsize 0.9*point_scale linewidth 1 " + colour + axes +
                      " " + title);
      }
    }
  return plot + "\n";
}

// Lower panel: 100·(T/T_Haff − 1) against ln t; kinetic-theory τ0 solid, own fit dashed.
std::string deviation_commands(const validation::Fig3Data& data, double x_max,
                               const std::string& onset_arrow) {
  std::string c = "  # Lower panel: relative deviation from Haff's law, per cent.\n";
  c += "  unset object; unset arrow; unset label; unset title; unset logscale y\n";
  c += "  set lmargin at screen 0.13; set rmargin at screen 0.96\n";
  c += "  set bmargin at screen 0.08; set tmargin at screen 0.37\n";
  c += "  set xrange [0:" + detail::number(x_max) + "]\n  set autoscale y\n";
  c += "  set format y '%g'\n  set ylabel 'T/T_{Haff} − 1  [%]'\n";
  c += "  set xlabel 'ln t,   t in units of σ(m/T_0)^{1/2}'\n  set ytics auto\n  set mytics 2\n";
  c += "  set key top left Left reverse horizontal spacing 1.0 samplen 2.5 box opaque "
       "font font_small\n";
  c += onset_arrow;
  c += "  set arrow from 0, 0 to " + detail::number(x_max) +
       ", 0 nohead linecolor rgb '#888888' dashtype solid linewidth 0.8 back\n";
  std::string plot;
  for (std::size_t k = 0; k < data.deviations.size(); ++k)
    detail::add_plot_element(
        plot, "$deviation" + std::to_string(k) +
                  " using 1:3:4 with filledcurves fillstyle transparent "
                  "solid 0.2 noborder linecolor rgb " +
                  detail::colour(deviation_colour(data, data.deviations[k].label)) + " notitle");
  for (std::size_t k = 0; k < data.deviations.size(); ++k) {
    const auto& d = data.deviations[k];
    detail::add_plot_element(
        plot, "$deviation" + std::to_string(k) + " using 1:2 with lines linecolor rgb " +
                  detail::colour(deviation_colour(data, d.label)) +
                  (d.is_theory ? " dashtype solid linewidth 1.3" : " dashtype (6,4) linewidth 1") +
                  " notitle");
  }
  // The key explains the line styles; the colours are the gases of the upper panel.
  detail::add_plot_element(plot,
                           "NaN with lines linecolor rgb '#444444' dashtype solid "
                           "linewidth 1.3 title 'Haff with kinetic-theory τ0'");
  detail::add_plot_element(plot,
                           "NaN with lines linecolor rgb '#444444' dashtype (6,4) "
                           "linewidth 1 title 'Haff with own fitted τ0'");
  return c + plot + "\n";
}

// Padded y range of the inset, from the data inside its ln t range; empty when none falls there.
std::optional<std::pair<double, double>> inset_range(double low, double high) {
  if (!std::isfinite(low) || !std::isfinite(high)) return std::nullopt;
  const double pad = 0.08 * std::max(high - low, 1e-6 * high);
  return std::make_pair(low - pad, high + pad);
}

// The rectangle on the upper panel that marks the region the inset magnifies.
std::string inset_commands_main(const validation::Fig3Data& data, double low, double high) {
  const auto range = inset_range(low, high);
  if (!range) return "";
  return "  set object 1 rectangle from " + detail::number(data.inset_log_t_min) + "," +
         detail::number(range->first) + " to " + detail::number(data.inset_log_t_max) + "," +
         detail::number(range->second) +
         " fillstyle empty border linecolor rgb '#555555' dashtype (2,3) front\n";
}

// The inset: a linear-axis magnification of inset_log_t_min ≤ ln t ≤ inset_log_t_max in the
// lower left of the upper panel, where the main plot is empty (T is still ≈ T0 there).
std::string inset_commands(const validation::Fig3Data& data, const std::vector<CurveRows>& curves,
                           double low, double high, bool two_panels) {
  const auto range = inset_range(low, high);
  if (!range) return "";
  std::string c = "  # Inset: magnification of " + detail::number(data.inset_log_t_min) +
                  " <= ln t <= " + detail::number(data.inset_log_t_max) +
                  ", y range fitted to the data there.\n";
  c += "  unset object 1; unset arrow; unset label; unset title; unset key; unset grid\n";
  c += "  set lmargin at screen 0.21; set rmargin at screen 0.47\n";
  c += two_panels ? "  set bmargin at screen 0.59; set tmargin at screen 0.81\n"
                  : "  set bmargin at screen 0.40; set tmargin at screen 0.68\n";
  c += "  unset logscale y\n  unset ytics\n  set y2tics mirror font font_small\n";
  c += "  set format y2 '%.3g'\n  set format x '%.2f'\n";
  c += "  set xtics 0.25 font font_small\n  set mxtics 5\n  set my2tics 2\n";
  c += "  set xlabel 'ln t' font font_small offset 0,0.6\n  unset ylabel\n";
  c += "  set object 2 rectangle from graph 0,0 to graph 1,1 behind fillcolor rgb 'white' "
       "fillstyle solid 1.0 noborder\n";
  c += "  set xrange [" + detail::number(data.inset_log_t_min) + ":" +
       detail::number(data.inset_log_t_max) + "]\n";
  c += "  set y2range [" + detail::number(range->first) + ":" + detail::number(range->second) +
       "]\n";
  c += temperature_plot(data, curves, false, " axes x1y2");
  // Back to the defaults the lower panel expects.
  c += "  unset object 2; unset y2tics; unset my2tics; set ytics; set xtics auto font ''\n";
  c += "  set mxtics 2; set format x '%g'; set xlabel font '' offset 0,0\n";
  return c;
}

}  // namespace

// The y range of the lower panel: every deviation up to x_limit (the whole run: a curve that
// left the panel after the clustering onset would hide how far the original gas departs), padded.
static std::pair<double, double> deviation_range(const std::vector<detail::Rows>& rows,
                                                 double x_limit) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& block : rows)
    for (const auto& r : block)
      if (r[0] <= x_limit && r[0] >= 1.0) {
        lo = std::min(lo, r[2]);
        hi = std::max(hi, r[3]);
      }
  if (!std::isfinite(lo)) return {-1.0, 1.0};
  const double pad = 0.15 * std::max(hi - lo, 0.1);
  return {lo - pad, hi + pad};
}

RenderedFigure render_fig3(const validation::Fig3Data& data, const RenderOptions& options) {
  detail::require_non_empty("Fig3Data.curves", data.curves.size());
  if (!(data.inset_log_t_max > data.inset_log_t_min)) {
    throw std::invalid_argument("Fig3Data.inset_log_t_max must exceed inset_log_t_min");
  }
  if (data.clustering_onset && !(*data.clustering_onset > 0.0)) {
    throw std::invalid_argument("Fig3Data.clustering_onset must be positive (it is drawn at ln t)");
  }

  detail::FigureScript script;
  script.basename = "fig3_temperature";
  script.canvas.png_height = data.deviations.empty() ? 900 : 1350;
  script.canvas.pdf_height = data.deviations.empty() ? 4.5 : 6.75;
  script.description =
      "Fig. 3 of Poeschel, Brilliantov, Schwager: temperature T/T0 against ln t; simulations "
      "solid,\nHaff's law T0/(1 + t/tau0)^2 dashed; lower panel 100 (T/T_Haff - 1). Data blocks: "
      "ln t, value, value - err, value + err.";

  std::vector<CurveRows> curves;
  double inset_low = std::numeric_limits<double>::infinity();
  double inset_high = -std::numeric_limits<double>::infinity();
  double lowest = std::numeric_limits<double>::infinity(), x_max = 0.0;
  for (std::size_t i = 0; i < data.curves.size(); ++i) {
    curves.push_back(curve_rows(data.curves[i], "Fig3Data.curves[" + std::to_string(i) + "]"));
    for (const auto& row : curves.back().rows) {
      if (row[1] > 0.0) lowest = std::min(lowest, row[1]);
      x_max = std::max(x_max, row[0]);
      if (row[0] >= data.inset_log_t_min && row[0] <= data.inset_log_t_max) {
        inset_low = std::min(inset_low, row[2]);
        inset_high = std::max(inset_high, row[3]);
      }
    }
    script.data.emplace_back("curve" + std::to_string(i), curves.back().rows);
  }
  std::vector<detail::Rows> deviations;
  for (std::size_t k = 0; k < data.deviations.size(); ++k) {
    deviations.push_back(
        deviation_rows(data.deviations[k], "Fig3Data.deviations[" + std::to_string(k) + "]"));
    script.data.emplace_back("deviation" + std::to_string(k), deviations.back());
  }
  x_max = std::ceil(x_max - 0.05);  // ln 3000 = 8.006 still ends the axis at 8

  std::string onset_arrow;
  if (data.clustering_onset) {
    const std::string x = detail::number(std::log(*data.clustering_onset));
    onset_arrow = "  set arrow from " + x + ", graph 0 to " + x +
                  ", graph 1 nohead dashtype (3,4) linecolor rgb '#555555' linewidth 1.2 back\n";
  }
  const bool two_panels = !data.deviations.empty();
  std::string& c = script.commands;
  c += "  set multiplot\n";
  if (!data.title.empty()) c += "  set title " + detail::quote(data.title) + "\n";
  c += "  set lmargin at screen 0.13; set rmargin at screen 0.96\n";
  c += std::string("  set bmargin at screen ") + (two_panels ? "0.40" : "0.12") +
       "; set tmargin at screen " + (data.title.empty() ? "0.96" : "0.93") + "\n";
  c += "  set xrange [0:" + detail::number(x_max) + "]\n";
  c += two_panels ? "  set format x ''\n  unset xlabel\n"
                  : "  set xlabel 'ln t,   t in units of σ(m/T_0)^{1/2}'\n";
  c += "  set ylabel 'T/T_0'\n";
  c += "  set logscale y\n  set format y '10^{%L}'\n";
  c += "  set mxtics 2\n  set tics scale 1.5,0.75\n";
  // Plotted against ln t ≥ 0, Haff's law stays near T0 on the left and falls to the lower right:
  // the inset goes to the empty lower left, the key to the lower right below the end of the
  // curves (the y range reaches one and a half decades below the lowest temperature for it).
  c += "  set key bottom right Left reverse spacing 1.1 samplen 3 box opaque font font_small\n";
  if (std::isfinite(lowest))
    c += "  set yrange [" + detail::number(std::pow(10.0, std::floor(std::log10(lowest)) - 1.5)) +
         ":1.3]\n";
  c += "  set grid xtics ytics linecolor rgb '#dddddd' dashtype solid\n";
  c += onset_arrow;
  if (data.clustering_onset)
    c += "  set label 'clustering onset' at " + detail::number(std::log(*data.clustering_onset)) +
         ", graph 0.27 rotate by 90 left offset character -0.7, 0 font font_small "
         "textcolor rgb '#555555' front\n";
  c += inset_commands_main(data, inset_low, inset_high);
  c += temperature_plot(data, curves, true, "");
  c += inset_commands(data, curves, inset_low, inset_high, two_panels);
  if (two_panels) {
    const auto [lo, hi] = deviation_range(deviations, x_max);
    c += deviation_commands(data, x_max, onset_arrow);
    c.insert(c.rfind("  plot "),
             "  set yrange [" + detail::number(lo) + ":" + detail::number(hi) + "]\n");
  }
  return detail::render(script, options);
}

}  // namespace molchaos::figures
