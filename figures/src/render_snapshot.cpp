// A snapshot of the original gas after the clustering onset: particles coloured by speed and the
// coarse-grained velocity field as arrows, where the vortices and clusters of §4 can be seen.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "figure_script.hpp"
#include "molchaos/figures/render.hpp"

namespace molchaos::figures {
namespace {

// Smallest positive spacing between distinct cell centres along one axis: the grid spacing.
double grid_spacing(std::vector<double> centres, double fallback) {
  std::sort(centres.begin(), centres.end());
  double spacing = fallback;
  for (std::size_t i = 1; i < centres.size(); ++i) {
    const double gap = centres[i] - centres[i - 1];
    if (gap > 1e-9 * fallback) spacing = std::min(spacing, gap);
  }
  return spacing;
}

}  // namespace

RenderedFigure render_snapshot(const validation::SnapshotData& data, const RenderOptions& options) {
  if (!(data.box > 0.0)) throw std::invalid_argument("SnapshotData.box must be positive");
  detail::require_non_empty("SnapshotData.x", data.x.size());
  detail::require_same_size("SnapshotData.y", data.y.size(), "SnapshotData.x", data.x.size());
  detail::require_same_size("SnapshotData.speed", data.speed.size(), "SnapshotData.x",
                            data.x.size());
  const auto cells = data.grid_x.size();
  detail::require_same_size("SnapshotData.grid_y", data.grid_y.size(), "SnapshotData.grid_x",
                            cells);
  detail::require_same_size("SnapshotData.grid_vx", data.grid_vx.size(), "SnapshotData.grid_x",
                            cells);
  detail::require_same_size("SnapshotData.grid_vy", data.grid_vy.size(), "SnapshotData.grid_x",
                            cells);

  detail::FigureScript script;
  script.basename = "fig_snapshot";
  script.description =
      "Snapshot of the original gas: particles (x, y, |v|/<v^2>^(1/2)) coloured by speed and the\n"
      "coarse-grained velocity field (cell centre x, y and the arrow dx, dy = scale * mean v).";
  script.canvas.png_width = 1100;
  script.canvas.png_height = 1000;
  script.canvas.pdf_width = 5.5;
  script.canvas.pdf_height = 5.0;

  detail::Rows particles;
  for (std::size_t i = 0; i < data.x.size(); ++i) {
    particles.push_back({data.x[i], data.y[i], data.speed[i]});
  }
  script.data.emplace_back("particles", particles);

  // Arrows are scaled so that the fastest cell's arrow spans 90% of a cell.
  double max_speed = 0.0;
  for (std::size_t i = 0; i < cells; ++i) {
    max_speed = std::max(max_speed, std::hypot(data.grid_vx[i], data.grid_vy[i]));
  }
  const double spacing =
      std::min(grid_spacing(data.grid_x, data.box), grid_spacing(data.grid_y, data.box));
  const double arrow_scale = max_speed > 0.0 ? 0.9 * spacing / max_speed : 0.0;
  if (cells > 0) {
    detail::Rows field;
    for (std::size_t i = 0; i < cells; ++i) {
      field.push_back({data.grid_x[i], data.grid_y[i], arrow_scale * data.grid_vx[i],
                       arrow_scale * data.grid_vy[i]});
    }
    script.data.emplace_back("field", field);
  }

  // Colour range: up to the 99th percentile of the speed, so that a few fast particles do not
  // wash out the rest.
  std::vector<double> speeds = data.speed;
  std::sort(speeds.begin(), speeds.end());
  const double cb_max = std::max(
      speeds[static_cast<std::size_t>(0.99 * static_cast<double>(speeds.size() - 1))], 1e-12);

  std::string& c = script.commands;
  std::string title = data.title;
  if (title.empty()) title = "t = " + detail::number(data.time);
  c += "  set title " + detail::quote(title) + "\n";
  c += "  set size ratio -1\n";
  c += "  set xrange [0:" + detail::number(data.box) +
       "]\n  set yrange [0:" + detail::number(data.box) + "]\n";
  c += "  set xlabel 'x  [σ]'\n  set ylabel 'y  [σ]'\n  set tics out scale 1.2 nomirror\n";
  c += "  set border linewidth 1\n";
  // Perceptually uniform (viridis-like) colour map.
  c += "  set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 "
       "'#fde725')\n";
  c += "  set cbrange [0:" + detail::number(cb_max) + "]\n";
  c += "  set cblabel '|v| / ⟨v^2⟩^{1/2}'\n  set colorbox user origin graph 1.03, graph 0 "
       "size graph 0.04, graph 1\n";
  c += "  set rmargin 12\n  unset key\n";
  c += "  # Arrows: velocity field scaled by " + detail::number(arrow_scale) +
       " (longest arrow = 0.9 cell).\n";
  c += "  plot $particles using 1:2:3 with points pointtype 7 pointsize 0.32*point_scale "
       "linecolor palette";
  if (cells > 0) {
    c += ", \\\n       $field using 1:2:3:4 with vectors head size screen 0.008,25 filled "
         "linecolor rgb 'black' linewidth 0.8";
  }
  c += "\n";
  return detail::render(script, options);
}

}  // namespace molchaos::figures
