// Fig. 3 of the paper: the temperature T(t)/T0 of the original and the randomized gas against
// ln t, with Haff's law (Eq. 2) dashed, the clustering onset marked, and an inset magnifying
// 2.5 ≤ ln t ≤ 3 where the paper sees a small systematic deviation.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {
namespace {

// Below this many points a curve is drawn with error bars; above, with a shaded error band.
constexpr std::size_t k_max_points_for_error_bars = 40;

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

}  // namespace

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
  script.description =
      "Fig. 3 of Poeschel, Brilliantov, Schwager: temperature T/T0 against ln t; simulations "
      "solid,\n"
      "Haff's law T0/(1 + t/tau0)^2 dashed. Data blocks: ln t, T/T0, T - err, T + err.";

  std::vector<CurveRows> curves;
  double inset_low = std::numeric_limits<double>::infinity();
  double inset_high = -std::numeric_limits<double>::infinity();
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < data.curves.size(); ++i) {
    curves.push_back(curve_rows(data.curves[i], "Fig3Data.curves[" + std::to_string(i) + "]"));
    for (const auto& row : curves.back().rows) {
      if (row[1] > 0.0) lowest = std::min(lowest, row[1]);
      if (row[0] >= data.inset_log_t_min && row[0] <= data.inset_log_t_max) {
        inset_low = std::min(inset_low, row[2]);
        inset_high = std::max(inset_high, row[3]);
      }
    }
    script.data.emplace_back("curve" + std::to_string(i), curves.back().rows);
  }

  // Plot elements: error bands first so that every line is drawn on top of them, then
  // simulations, then the theory lines (dashed, so that coinciding curves stay visible).
  const auto plot_elements = [&](bool with_titles, const std::string& axes) {
    std::vector<std::string> elements;
    for (std::size_t i = 0; i < curves.size(); ++i) {
      if (!curves[i].has_error || curves[i].rows.size() <= k_max_points_for_error_bars) continue;
      elements.push_back("$curve" + std::to_string(i) +
                         " using 1:3:4 with filledcurves fillstyle transparent solid 0.25 "
                         "noborder linecolor rgb " +
                         detail::colour(i) + axes + " notitle");
    }
    for (int pass = 0; pass < 2; ++pass) {
      for (std::size_t i = 0; i < curves.size(); ++i) {
        const auto& curve = data.curves[i];
        if (curve.is_theory != (pass == 1)) continue;
        const std::string block = "$curve" + std::to_string(i);
        const std::string title =
            with_titles && !curve.label.empty() ? "title " + detail::quote(curve.label) : "notitle";
        const std::string style =
            "linecolor rgb " + detail::colour(i) +
            (curve.is_theory ? " dashtype (8,5) linewidth 1.3" : " dashtype solid linewidth 1");
        if (curves[i].has_error && curves[i].rows.size() <= k_max_points_for_error_bars) {
          elements.push_back(block + " using 1:2:3:4 with yerrorlines pointtype 7 " +
                             "pointsize 0.8*point_scale " + style + axes + " " + title);
        } else {
          elements.push_back(block + " using 1:2 with lines " + style + axes + " " + title);
        }
      }
    }
    std::string plot = "  plot ";
    for (std::size_t k = 0; k < elements.size(); ++k) {
      plot += (k == 0 ? "" : ", \\\n       ") + elements[k];
    }
    return plot + "\n";
  };

  const bool has_inset = std::isfinite(inset_low) && std::isfinite(inset_high);
  double inset_y_min = 0.0, inset_y_max = 0.0;
  if (has_inset) {
    const double pad = 0.08 * std::max(inset_high - inset_low, 1e-6 * inset_high);
    inset_y_min = inset_low - pad;
    inset_y_max = inset_high + pad;
  }

  std::string& c = script.commands;
  c += "  set multiplot\n";
  if (!data.title.empty()) c += "  set title " + detail::quote(data.title) + "\n";
  c += "  set lmargin at screen 0.13; set rmargin at screen 0.96\n";
  c += "  set bmargin at screen 0.12; set tmargin at screen " +
       std::string(data.title.empty() ? "0.96" : "0.91") + "\n";
  c += "  set xlabel 'ln t,   t in units of σ(m/T_0)^{1/2}'\n";
  c += "  set ylabel 'T/T_0'\n";
  c += "  set logscale y\n  set format y '10^{%L}'\n";
  c += "  set mxtics 2\n  set tics scale 1.5,0.75\n";
  // Plotted against ln t ≥ 0, Haff's law stays near T0 on the left and falls to the lower right:
  // the inset goes to the empty lower left.
  // The key goes to the lower right, below the end of the curves: the y range reaches one and a
  // half decades below the lowest temperature to make room for it.
  c += "  set key bottom right Left reverse spacing 1.2 samplen 2.5 box opaque font font_small\n";
  if (std::isfinite(lowest))
    c += "  set yrange [" + detail::number(std::pow(10.0, std::floor(std::log10(lowest)) - 1.5)) +
         ":1.3]\n";
  c += "  set grid xtics ytics linecolor rgb '#dddddd' dashtype solid\n";
  if (data.clustering_onset) {
    const std::string x = detail::number(std::log(*data.clustering_onset));
    // Drawn behind the (opaque) key; the inset sits in the lower left, away from the onset.
    c += "  set arrow from " + x + ", graph 0 to " + x +
         ", graph 1 nohead dashtype (3,4) linecolor rgb '#555555' linewidth 1.2 back\n";
    c += "  set label 'clustering onset' at " + x +
         ", graph 0.42 rotate by 90 left offset character -0.7, 0 font font_small "
         "textcolor rgb '#555555' front\n";
  }
  if (has_inset) {
    // Mark the magnified region on the main plot.
    c += "  set object 1 rectangle from " + detail::number(data.inset_log_t_min) + "," +
         detail::number(inset_y_min) + " to " + detail::number(data.inset_log_t_max) + "," +
         detail::number(inset_y_max) +
         " fillstyle empty border linecolor rgb '#555555' dashtype (2,3) front\n";
  }
  c += plot_elements(true, "");

  if (has_inset) {
    c += "  # Inset: magnification of " + detail::number(data.inset_log_t_min) +
         " <= ln t <= " + detail::number(data.inset_log_t_max) +
         ", y range fitted to the data there.\n";
    c += "  unset object 1; unset arrow; unset label; unset title; unset key; unset grid\n";
    // Lower left, where the main plot is empty (T is still ≈ T0 there); y tic labels on the right.
    c += "  set lmargin at screen 0.21; set rmargin at screen 0.47\n";
    c += "  set bmargin at screen 0.40; set tmargin at screen 0.68\n";
    c += "  unset logscale y\n  unset ytics\n  set y2tics mirror font font_small\n";
    c += "  set format y2 '%.3g'\n  set format x '%.2f'\n";
    c += "  set xtics 0.25 font font_small\n  set mxtics 5\n  set my2tics 2\n";
    c += "  set xlabel 'ln t' font font_small offset 0,0.6\n  unset ylabel\n";
    c += "  set object 2 rectangle from graph 0,0 to graph 1,1 behind fillcolor rgb 'white' "
         "fillstyle solid 1.0 noborder\n";
    c += "  set xrange [" + detail::number(data.inset_log_t_min) + ":" +
         detail::number(data.inset_log_t_max) + "]\n";
    c +=
        "  set y2range [" + detail::number(inset_y_min) + ":" + detail::number(inset_y_max) + "]\n";
    c += plot_elements(false, " axes x1y2");
  }
  return detail::render(script, options);
}

}  // namespace molchaos::figures
