// Work–precision diagram of the simulation: the relative standard error of the ensemble mean of A
// against the CPU seconds spent, one line per system size N (SE = sd_run sqrt(c_run / t) for t
// seconds spent on runs of c_run seconds each), the measured ensembles as points, the targets as
// horizontal lines.
#include <cmath>
#include <stdexcept>
#include <string>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {

RenderedFigure render_simulation_cost(const validation::SimulationWorkPrecisionData& data,
                                      const RenderOptions& options) {
  detail::require_non_empty("SimulationWorkPrecisionData.points", data.points.size());
  detail::FigureScript script;
  script.basename = k_simulation_cost_figure;
  script.description =
      "Simulation work-precision: relative standard error of A against CPU seconds, per N.";
  detail::begin_log_log(script, data.title, "CPU seconds spent on the ensemble",
                        "relative standard error of A");
  std::string plot;
  const auto add = [&plot](const std::string& element) { detail::add_plot_element(plot, element); };
  for (std::size_t k = 0; k < data.points.size(); ++k) {
    const auto& p = data.points[k];
    const std::string field = "SimulationWorkPrecisionData.points[" + std::to_string(k) + "]";
    if (!(p.cpu_seconds_per_run > 0.0) || !(p.relative_sd_per_run > 0.0) || p.seeds < 1)
      throw std::invalid_argument(field +
                                  ": cpu_seconds_per_run, relative_sd_per_run and seeds "
                                  "must be positive (log axes)");
    detail::Rows line, measured;
    for (int j = 0; j <= 40; ++j) {  // from 2 runs to 10^4 times that
      const double t = 2.0 * p.cpu_seconds_per_run * std::pow(10.0, 0.1 * j);
      line.push_back({t, p.relative_sd_per_run * std::sqrt(p.cpu_seconds_per_run / t)});
    }
    measured.push_back({p.seeds * p.cpu_seconds_per_run,
                        p.relative_sd_per_run / std::sqrt(static_cast<double>(p.seeds))});
    const std::string name = "n" + std::to_string(k);
    script.data.emplace_back(name, line);
    script.data.emplace_back(name + "m", measured);
    add("$" + name + " using 1:2 with lines linewidth 2 linecolor rgb " + detail::colour(k) +
        " title " + detail::quote("N = " + detail::label_number(static_cast<double>(p.particles))));
    add("$" + name +
        "m using 1:2 with points pointtype 7 pointsize 1.5*point_scale linecolor rgb " +
        detail::colour(k) + " notitle");
  }
  const char* dashes[] = {"(6,4)", "(2,3)", "(10,3,2,3)"};
  for (std::size_t k = 0; k < data.targets.size(); ++k)
    add(detail::number(data.targets[k]) + " with lines dashtype " + dashes[k % 3] +
        " linecolor rgb '#555555' title " +
        detail::quote("target " + detail::label_number(100.0 * data.targets[k]) + " %"));
  script.commands += plot + "\n";
  return detail::render(script, options);
}

}  // namespace molchaos::figures
