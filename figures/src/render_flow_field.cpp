// Flow-field figure: per time (rows) and gas (column pairs), the coarse-grained velocity as arrows
// over its vorticity (colour), and the density relative to the mean (colour).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"
#include "molchaos/validation/flow_field.hpp"

namespace molchaos::figures {
namespace {

void check(const validation::FlowFieldPanel& p) {
  const auto n = static_cast<std::size_t>(p.cells) * static_cast<std::size_t>(p.cells);
  if (p.cells < 2 || !(p.box > 0)) throw std::invalid_argument("FlowFieldPanel.cells, box");
  detail::require_same_size("FlowFieldPanel.vx", p.vx.size(), "cells²", n);
  detail::require_same_size("FlowFieldPanel.vy", p.vy.size(), "cells²", n);
  detail::require_same_size("FlowFieldPanel.vorticity", p.vorticity.size(), "cells²", n);
  detail::require_same_size("FlowFieldPanel.relative_density", p.relative_density.size(), "cells²",
                            n);
}

}  // namespace

RenderedFigure render_flow_field(const validation::FlowFieldData& data,
                                 const RenderOptions& options) {
  detail::require_non_empty("FlowFieldData.rows", data.rows.size());
  const std::size_t columns = data.rows.front().size();
  detail::require_non_empty("FlowFieldData.rows[0]", columns);
  detail::FigureScript script;
  script.basename = "fig_flow_field";
  script.description =
      "Coarse-grained fields: per panel pair, the mean velocity / sqrt(T) as arrows over the\n"
      "vorticity (colour), and the number of particles per cell over its mean (colour).";
  script.canvas.png_width = 700 * static_cast<int>(columns);
  script.canvas.png_height = 330 * static_cast<int>(data.rows.size());
  script.canvas.pdf_width = 3.5 * static_cast<double>(columns);
  script.canvas.pdf_height = 1.65 * static_cast<double>(data.rows.size());
  std::string& c = script.commands;
  c += "  set multiplot layout " + std::to_string(data.rows.size()) + "," +
       std::to_string(2 * columns) + "\n";
  c += "  set size ratio -1\n  unset key\n  set tics out nomirror\n  set format x ''\n"
       "  set format y ''\n";
  for (std::size_t r = 0; r < data.rows.size(); ++r) {
    detail::require_same_size("FlowFieldData.rows[r]", data.rows[r].size(), "columns", columns);
    for (std::size_t col = 0; col < columns; ++col) {
      const auto& p = data.rows[r][col];
      check(p);
      const double w = p.box / p.cells;
      detail::Rows vort, dens, arrows;
      double vmax = 1e-12, wmax = 1e-12, dmax = 1.0;
      for (int y = 0; y < p.cells; ++y)
        for (int x = 0; x < p.cells; ++x) {
          const auto i = static_cast<std::size_t>(y * p.cells + x);
          const double cx = (x + 0.5) * w, cy = (y + 0.5) * w;
          vort.push_back({cx, cy, p.vorticity[i]});
          dens.push_back({cx, cy, p.relative_density[i]});
          arrows.push_back({cx, cy, p.vx[i], p.vy[i]});
          vmax = std::max(vmax, std::hypot(p.vx[i], p.vy[i]));
          wmax = std::max(wmax, std::abs(p.vorticity[i]));
          dmax = std::max(dmax, p.relative_density[i]);
        }
      for (auto& a : arrows) {
        a[2] *= 0.9 * w / vmax;
        a[3] *= 0.9 * w / vmax;
      }
      const std::string tag = std::to_string(r) + "_" + std::to_string(col);
      script.data.emplace_back("vort" + tag, vort);
      script.data.emplace_back("dens" + tag, dens);
      script.data.emplace_back("arrows" + tag, arrows);
      const std::string range = "[0:" + detail::number(p.box) + "]";
      c += "  set xrange " + range + "\n  set yrange " + range + "\n";
      c += "  set palette defined (-1 '#2166ac', 0 '#f7f7f7', 1 '#b2182b')\n";
      c += "  set cbrange [" + detail::number(-wmax) + ":" + detail::number(wmax) + "]\n";
      c += "  set title " + detail::quote(p.title + ": flow, vorticity") + " font ',9'\n";
      c += "  plot $vort" + tag + " using 1:2:3 with image, $arrows" + tag +
           " using 1:2:3:4 with vectors head size screen 0.004,25 filled lc rgb 'black'\n";
      c += "  set palette defined (0 '#ffffff', 1 '#fdae61', 2 '#d7191c', 3 '#40004b')\n";
      c += "  set cbrange [0:" + detail::number(dmax) + "]\n";
      c += "  set title " + detail::quote(p.title + ": density / mean") + " font ',9'\n";
      c += "  plot $dens" + tag + " using 1:2:3 with image\n";
    }
  }
  return detail::render(script, options);
}

}  // namespace molchaos::figures
