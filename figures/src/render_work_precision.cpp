// Work–precision diagram of the theory's quadrature: CPU time against the error reached (and the
// error the quadrature estimated), each point labelled by the tolerance that was requested.
#include <cmath>
#include <stdexcept>
#include <string>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {

RenderedFigure render_work_precision(const validation::WorkPrecisionData& data,
                                     const RenderOptions& options, const std::string& basename) {
  if (basename.empty() || basename.find('/') != std::string::npos) {
    throw std::invalid_argument("render_work_precision: basename '" + basename +
                                "' must be a plain, non-empty file stem");
  }
  detail::require_non_empty("WorkPrecisionData.points", data.points.size());
  detail::Rows reached, estimated;
  std::size_t exact = 0;
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const auto& point = data.points[i];
    const std::string field = "WorkPrecisionData.points[" + std::to_string(i) + "]";
    if (!(point.seconds > 0.0)) {
      throw std::invalid_argument(field + ".seconds is not positive (log axis)");
    }
    if (!(point.requested_tolerance > 0.0)) {
      throw std::invalid_argument(field + ".requested_tolerance is not positive (log axis)");
    }
    // An error of exactly zero has no place on a log axis: it is counted in the key instead.
    if (point.max_error_reached > 0.0) {
      reached.push_back({point.max_error_reached, point.seconds, point.requested_tolerance});
    } else {
      ++exact;
    }
    if (point.max_error_estimate > 0.0) {
      estimated.push_back({point.max_error_estimate, point.seconds, point.requested_tolerance});
    }
  }
  if (reached.empty() && estimated.empty()) {
    throw std::invalid_argument(
        "WorkPrecisionData.points: no positive max_error_reached or max_error_estimate");
  }

  detail::FigureScript script;
  script.basename = basename;
  script.description =
      "Work-precision diagram of the quadrature: columns error, CPU seconds, requested tolerance.";
  detail::begin_log_log(script, data.title, "error  (max over coefficients)", "CPU time  [s]");
  std::string& c = script.commands;
  c += "  set tics scale 1.5,0.75\n  set offsets graph 0.05, graph 0.15, graph 0.1, graph 0.1\n";
  // "10^{-6}" for a power of ten, "2.5·10^{-7}" otherwise.
  c += "  tolerance_label(t) = abs(t / 10**floor(log10(t) + 1e-9) - 1) < 1e-6 ? "
       "sprintf('10^{%d}', floor(log10(t) + 0.5)) : gprintf('%.1t·10^{%T}', t)\n";
  std::string plot;
  const auto add = [&plot](const std::string& element) { detail::add_plot_element(plot, element); };
  if (!reached.empty()) {
    script.data.emplace_back("reached", reached);
    std::string title = "error reached |computed − exact|";
    if (exact > 0) title += " (" + std::to_string(exact) + " exact, not shown)";
    add("$reached using 1:2 with linespoints pointtype 7 pointsize 1.5*point_scale linecolor rgb " +
        detail::colour(1) + " title " + detail::quote(title));
    add("$reached using 1:2:(tolerance_label($3)) with labels left offset character 0.9,0.5 "
        "font font_small textcolor rgb " +
        detail::colour(1) + " notitle");
  }
  if (!estimated.empty()) {
    script.data.emplace_back("estimated", estimated);
    add("$estimated using 1:2 with linespoints pointtype 6 pointsize 1.5*point_scale dashtype "
        "(6,4) linecolor rgb " +
        detail::colour(2) + " title 'error estimate'");
  }
  add("keyentry with labels textcolor rgb " + detail::colour(1) +
      " title 'labels: requested tolerance'");
  c += plot + "\n";
  return detail::render(script, options);
}

}  // namespace molchaos::figures
