// Flow-field figure: per time (rows) and gas (columns), the vorticity in units of its noise in a
// gas without correlations (colour), the flow as arrows, and where the density stands two such
// units above its mean (solid contours) or below it (dashed). One unit and one colour range for
// every panel, so that the gases and times compare at a glance.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"
#include "molchaos/validation/flow_field.hpp"

namespace molchaos::figures {
namespace {

// The density contours, in noise levels of a gas without correlations: its field, a sum of many
// independent modes and so nearly Gaussian, lies beyond 2 of them on 2.3 % of the area each side.
constexpr double k_density_contour = 2.0;

void check(const validation::FlowFieldPanel& p) {
  const auto n = static_cast<std::size_t>(p.cells) * static_cast<std::size_t>(p.cells);
  if (p.cells < 2 || !(p.box > 0)) throw std::invalid_argument("FlowFieldPanel.cells, box");
  if (!(p.density_noise > 0) || !(p.vorticity_noise > 0))
    throw std::invalid_argument("FlowFieldPanel.density_noise, vorticity_noise: must be > 0");
  detail::require_same_size("FlowFieldPanel.vx", p.vx.size(), "cells²", n);
  detail::require_same_size("FlowFieldPanel.vy", p.vy.size(), "cells²", n);
  detail::require_same_size("FlowFieldPanel.vorticity", p.vorticity.size(), "cells²", n);
  detail::require_same_size("FlowFieldPanel.relative_density", p.relative_density.size(), "cells²",
                            n);
}

// The figure's two scales: the arrow length of the fastest flow, and the colour range of the
// vorticity in noise levels (whole units, at least 3, so that a gas without correlations fills
// only the middle of the range).
struct Scales {
  double speed = 1e-12;
  double vorticity = 3.0;
};

Scales common_scales(const validation::FlowFieldData& data) {
  Scales s;
  for (const auto& row : data.rows)
    for (const auto& p : row) {
      check(p);
      for (std::size_t i = 0; i < p.vx.size(); ++i) {
        s.speed = std::max(s.speed, std::hypot(p.vx[i], p.vy[i]));
        s.vorticity =
            std::max(s.vorticity, std::ceil(std::abs(p.vorticity[i]) / p.vorticity_noise));
      }
    }
  return s;
}

// The data blocks of one panel (`tag` names them): the vorticity image, the arrows (about 12 per
// side, however fine the grid) and the density grid (scan lines apart, for gnuplot's contours).
void add_panel_data(detail::FigureScript& script, const validation::FlowFieldPanel& p,
                    const std::string& tag, double speed) {
  const double w = p.box / p.cells;
  const int stride = std::max(1, p.cells / 12);
  detail::Rows vort, dens, arrows;
  for (int y = 0; y < p.cells; ++y) {
    for (int x = 0; x < p.cells; ++x) {
      const auto i = static_cast<std::size_t>(y * p.cells + x);
      const double cx = (x + 0.5) * w, cy = (y + 0.5) * w;
      vort.push_back({cx, cy, p.vorticity[i] / p.vorticity_noise});
      dens.push_back({cx, cy, (p.relative_density[i] - 1.0) / p.density_noise});
      if (x % stride == 0 && y % stride == 0)
        arrows.push_back(
            {cx, cy, 0.9 * stride * w * p.vx[i] / speed, 0.9 * stride * w * p.vy[i] / speed});
    }
    dens.push_back({});
  }
  script.data.emplace_back("vort" + tag, vort);
  script.data.emplace_back("dens" + tag, dens);
  script.data.emplace_back("arrows" + tag, arrows);
}

// Contour tables $dense<tag> and $sparse<tag> of the density grid, made before the multiplot.
std::string contour_tables(const std::string& tag) {
  std::string c;
  for (const auto& [name, level] :
       {std::pair{"dense", k_density_contour}, std::pair{"sparse", -k_density_contour}})
    c += "  set cntrparam levels discrete " + detail::number(level) + "\n  set table $" + name +
         tag + "\n  splot $dens" + tag + " using 1:2:3 with lines notitle\n  unset table\n";
  return c;
}

void draw_panel(std::string& c, const validation::FlowFieldPanel& p, const std::string& tag) {
  const std::string range = "[0:" + detail::number(p.box) + "]";
  c += "  set xrange " + range + "\n  set yrange " + range + "\n";
  c += "  set title " + detail::quote(p.title) + " font ',11'\n";
  c += "  plot $vort" + tag + " using 1:2:3 with image, $arrows" + tag +
       " using 1:2:3:4 with vectors head size screen 0.004,25 filled lc rgb 'black', $dense" + tag +
       " using 1:2 with lines lw 1.5 lc rgb '#7f3b08', $sparse" + tag +
       " using 1:2 with lines lw 1.5 dt 2 lc rgb '#2d004b'\n";
}

// The name of the data blocks of the panel in row r, column col.
std::string panel_tag(std::size_t r, std::size_t col) {
  return std::to_string(r) + "_" + std::to_string(col);
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
// each its own multiplot page, which gnuplot's `gif animate` turns into a frame). One colour bar,
// in the right margin, for every panel.
detail::FigureScript flow_field_script(const validation::FlowFieldData& data, bool animated) {
  const std::size_t columns = checked_columns(data);
  const Scales scale = common_scales(data);
  const auto rows = data.rows.size();
  detail::FigureScript script;
  script.basename = animated ? "fig_flow_field_animation" : "fig_flow_field";
  script.image_stem = "fig_flow_field";
  script.description =
      std::string(animated ? "The flow-field figure as an animation, one frame per time.\n" : "") +
      "Flow and density fields of the long waves: the vorticity in units of its standard\n"
      "deviation in a gas without correlations (colour, one range for every panel), the mean\n"
      "velocity as arrows (one scale for the whole figure, longest arrow " +
      detail::label_number(scale.speed) +
      " sqrt(T)),\nand contours where the density stands 2 such units above its mean (solid) or\n"
      "below it (dashed).";
  script.canvas.png_width = 360 * static_cast<int>(columns) + 110;
  script.canvas.png_height = animated ? 380 : 340 * static_cast<int>(rows);
  script.canvas.pdf_width = 2.2 * static_cast<double>(columns) + 0.7;
  script.canvas.pdf_height = 2.1 * static_cast<double>(animated ? 1 : rows);
  // 0.4 s per frame: ~10 s for the reproduction's 24 frames
  if (animated) script.gif_frame_delay = 40;
  std::string& c = script.commands;
  c += "  set contour base\n  unset surface\n  set view map\n";
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t col = 0; col < columns; ++col) {
      add_panel_data(script, data.rows[r][col], panel_tag(r, col), scale.speed);
      c += contour_tables(panel_tag(r, col));
    }
  c += "  unset contour\n";
  c += "  set palette defined (-1 '#2166ac', 0 '#f7f7f7', 1 '#b2182b')\n";
  c += "  set cbrange [" + detail::number(-scale.vorticity) + ":" +
       detail::number(scale.vorticity) + "]\n";
  c += "  set cblabel 'vorticity in noise units'\n";
  // A frame has one row: its titles need a larger share of its height than the still figure's.
  const std::string top = animated ? "0.86" : "0.94";
  const std::string layout = "  set multiplot layout " + std::to_string(animated ? 1 : rows) + "," +
                             std::to_string(columns) +
                             " margins screen 0.02, screen 0.86, screen 0.02, screen " + top +
                             " spacing screen 0.01, screen 0.05\n";
  for (std::size_t r = 0; r < rows; ++r) {
    if (animated || r == 0)
      c += layout + k_panel_settings +
           "  set colorbox user origin screen 0.89, screen 0.15 size screen 0.025, screen 0.7\n";
    for (std::size_t col = 0; col < columns; ++col)
      draw_panel(c, data.rows[r][col], panel_tag(r, col));
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
