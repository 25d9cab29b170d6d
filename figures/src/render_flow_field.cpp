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

// Common scales, so that the gases and times compare at a glance: one arrow length for the whole
// figure, one vorticity range and one density range per time (row).
struct Scales {
  double speed = 1e-12;
  std::vector<double> vorticity, density;
};

Scales common_scales(const validation::FlowFieldData& data) {
  Scales s;
  for (const auto& row : data.rows) {
    double w = 1e-12, d = 1e-12;
    for (const auto& p : row) {
      check(p);
      for (std::size_t i = 0; i < p.vx.size(); ++i) {
        s.speed = std::max(s.speed, std::hypot(p.vx[i], p.vy[i]));
        w = std::max(w, std::abs(p.vorticity[i]));
        d = std::max(d, std::abs(p.relative_density[i] - 1.0));
      }
    }
    s.vorticity.push_back(w);
    s.density.push_back(d);
  }
  return s;
}

// One row of panel pairs (flow over vorticity, density) with the given scales; `tag` names the
// row's data blocks.
void draw_row(detail::FigureScript& script, const std::vector<validation::FlowFieldPanel>& row,
              const std::string& tag, double speed, double vorticity, double density) {
  std::string& c = script.commands;
  for (std::size_t col = 0; col < row.size(); ++col) {
    const auto& p = row[col];
    const double w = p.box / p.cells;
    // about 12 arrows per side, however fine the grid
    const int stride = std::max(1, p.cells / 12);
    detail::Rows vort, dens, arrows;
    for (int y = 0; y < p.cells; ++y)
      for (int x = 0; x < p.cells; ++x) {
        const auto i = static_cast<std::size_t>(y * p.cells + x);
        const double cx = (x + 0.5) * w, cy = (y + 0.5) * w;
        vort.push_back({cx, cy, p.vorticity[i]});
        dens.push_back({cx, cy, p.relative_density[i]});
        if (x % stride == 0 && y % stride == 0)
          arrows.push_back(
              {cx, cy, 0.9 * stride * w * p.vx[i] / speed, 0.9 * stride * w * p.vy[i] / speed});
      }
    const std::string t = tag + "_" + std::to_string(col);
    script.data.emplace_back("vort" + t, vort);
    script.data.emplace_back("dens" + t, dens);
    script.data.emplace_back("arrows" + t, arrows);
    const std::string range = "[0:" + detail::number(p.box) + "]";
    c += "  set xrange " + range + "\n  set yrange " + range + "\n";
    c += "  set palette defined (-1 '#2166ac', 0 '#f7f7f7', 1 '#b2182b')\n";
    c += "  set cbrange [" + detail::number(-vorticity) + ":" + detail::number(vorticity) + "]\n";
    c += "  set title " + detail::quote(p.title + ": flow, vorticity") + " font ',11'\n";
    c += "  plot $vort" + t + " using 1:2:3 with image, $arrows" + t +
         " using 1:2:3:4 with vectors head size screen 0.004,25 filled lc rgb 'black'\n";
    c += "  set palette defined (-1 '#01665e', 0 '#f5f5f5', 1 '#8c510a')\n";
    c += "  set cbrange [" + detail::number(1.0 - density) + ":" + detail::number(1.0 + density) +
         "]\n";
    c += "  set title " + detail::quote(p.title + ": density / mean") + " font ',11'\n";
    c += "  plot $dens" + t + " using 1:2:3 with image\n";
  }
}

// Every row has as many panels as the first, and at least one.
std::size_t checked_columns(const validation::FlowFieldData& data) {
  detail::require_non_empty("FlowFieldData.rows", data.rows.size());
  const std::size_t columns = data.rows.front().size();
  detail::require_non_empty("FlowFieldData.rows[0]", columns);
  for (const auto& row : data.rows)
    detail::require_same_size("FlowFieldData.rows[r]", row.size(), "columns", columns);
  return columns;
}

constexpr const char* k_panel_settings =
    "  set size ratio -1\n  unset key\n  set tics out nomirror\n  set format x ''\n"
    "  set format y ''\n";

// The still figure (all times in one multiplot, a row each) or the animation (a frame per time,
// each its own multiplot page, which gnuplot's `gif animate` turns into a frame).
detail::FigureScript flow_field_script(const validation::FlowFieldData& data, bool animated) {
  const std::size_t columns = checked_columns(data);
  const Scales scale = common_scales(data);
  const auto rows = data.rows.size();
  detail::FigureScript script;
  script.basename = animated ? "fig_flow_field_animation" : "fig_flow_field";
  script.image_stem = "fig_flow_field";
  script.description =
      std::string(animated ? "The flow-field figure as an animation, one frame per time.\n" : "") +
      "Flow and density fields: per panel pair, the mean velocity / sqrt(T) as arrows over the\n"
      "vorticity (colour), and the density over its mean (colour). One arrow scale for the whole\n"
      "figure (longest arrow: " +
      detail::label_number(scale.speed) + " sqrt(T)); colour ranges shared by the panels of a " +
      (animated ? "frame." : "row.");
  script.canvas.png_width = (animated ? 520 : 700) * static_cast<int>(columns);
  script.canvas.png_height = 330 * static_cast<int>(animated ? 1 : rows);
  script.canvas.pdf_width = 3.5 * static_cast<double>(columns);
  script.canvas.pdf_height = 1.65 * static_cast<double>(rows);
  // 0.4 s per frame: ~10 s for the reproduction's 24 frames
  if (animated) script.gif_frame_delay = 40;
  std::string& c = script.commands;
  const std::string layout =
      std::to_string(animated ? 1 : rows) + "," + std::to_string(2 * columns);
  for (std::size_t r = 0; r < rows; ++r) {
    if (animated || r == 0) c += "  set multiplot layout " + layout + "\n" + k_panel_settings;
    draw_row(script, data.rows[r], std::to_string(r), scale.speed, scale.vorticity[r],
             scale.density[r]);
    if (animated) c += "  unset multiplot\n";
  }
  return script;
}

}  // namespace

RenderedFigure render_flow_field(const validation::FlowFieldData& data,
                                 const RenderOptions& options) {
  return detail::render(flow_field_script(data, false), options);
}

RenderedFigure render_flow_field_animation(const validation::FlowFieldData& data,
                                           const RenderOptions& options) {
  return detail::render(flow_field_script(data, true), options);
}

}  // namespace molchaos::figures
