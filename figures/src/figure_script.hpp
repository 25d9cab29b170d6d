// The machinery shared by every figure: a gnuplot script with its data inline (written through
// gnuplot-iostream), run once per terminal, its outputs renamed into place only when complete.
#pragma once

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "molchaos/figures/render.hpp"

namespace molchaos::figures::detail {

/// One table of numbers, row by row; written into the script as a gnuplot data block.
using Rows = std::vector<std::vector<double>>;

/// Size and font of the two terminals; the plot commands are shared between them.
struct Canvas {
  int png_width = 1200, png_height = 900;    ///< pixels
  double pdf_width = 6.0, pdf_height = 4.5;  ///< inches
};

struct FigureScript {
  std::string basename;                            ///< file stem, e.g. "fig4_A_of_eps"
  std::string description;                         ///< comment lines at the top of the script
  std::vector<std::pair<std::string, Rows>> data;  ///< data block name (without '$') and rows
  std::string commands;                            ///< plot commands, run once per terminal
  Canvas canvas;
  /// > 0: one animated GIF (gnuplot's `gif animate`, each page a frame, this many 1/100 s apart,
  /// the PNG's size) instead of the PNG and PDF
  int gif_frame_delay = 0;
  std::string image_stem;  ///< the images' file stem when it is not `basename` (the script's)
};

/// Writes <basename>.gp and the requested images into options.output_directory.
RenderedFigure render(const FigureScript& script, const RenderOptions& options);

/// A gnuplot string literal (single-quoted, so enhanced-text markup still applies).
std::string quote(const std::string& text);

/// A number as gnuplot reads it back exactly.
std::string number(double value);

/// A number for a label: six significant digits (0.05, not 0.050000000000000003).
std::string label_number(double value);

/// Colour-blind-safe line colours (Okabe–Ito), cycled.
std::string colour(std::size_t index);

/// Throws std::invalid_argument("<field> ...") unless sizes agree.
void require_same_size(const std::string& field, std::size_t size, const std::string& other_field,
                       std::size_t other_size);
void require_non_empty(const std::string& field, std::size_t size);

/// The panels of a figure drawn per state point: the (dimension, density) pairs of `rows` (any
/// rows with those members), in order; an error when there are none.
template <class Rows>
std::set<std::pair<int, double>> state_panels(const Rows& rows) {
  std::set<std::pair<int, double>> panels;
  for (const auto& r : rows) panels.emplace(r.dimension, r.density);
  require_non_empty("rows", panels.size());
  return panels;
}

/// Title, log-log axes with 10^k tick labels, axis labels, boxed key and light grid of a
/// work-precision diagram.
void begin_log_log(FigureScript& script, const std::string& title, const std::string& xlabel,
                   const std::string& ylabel);

/// Appends one element to a plot command being built ("  plot a, \\\n       b").
void add_plot_element(std::string& plot, const std::string& element);

/// The name of a data block: prefix followed by index ("p0_s" and 3 give "p0_s3").
std::string block_name(const std::string& prefix, std::size_t index);
/// "p<panel>_s<series>": the block of one series of one panel.
std::string panel_block_name(std::size_t panel, std::size_t series);

/// Stores rows as data block `block` and appends "$block using 1:2:3 with <style>" in colour
/// `colour` to the plot command; an empty title gives notitle.
void add_series(FigureScript& script, std::string& plot, const std::string& block, Rows rows,
                const std::string& style, std::size_t colour, const std::string& title);

/// "d = 2, n = 0.1": the title of a panel of one dimension and density.
std::string dimension_density_title(int dimension, double density);

/// The symbol (gnuplot point type) and colour index of a gas, the same in every figure: the
/// paper's filled triangle for the original gas (`none`), squares for the shuffled ones (`paper`
/// filled, `flux` open), an open circle for `dsmc`; `index` picks for any other.
std::string gas_point_type(const std::string& mode, std::size_t index);
std::size_t gas_colour_index(const std::string& mode, std::size_t index);
/// "with yerrorbars pointtype … pointsize … linecolor … linewidth 1 title '<title>'": a gas's
/// points with error bars, in its symbol and colour.
std::string gas_points(const std::string& mode, std::size_t index, const std::string& title);

/// The title "n = <density>" and the ε axis (set_epsilon_axis) of one panel against ε.
void set_density_panel(std::string& commands, double density, double eps_min, double eps_max);

/// The ε axis of one panel: the points' range with 4 % margins; for a panel of one ε, a window of
/// ±0.02 around it with that ε as its only tick (autoscaled, the series' sideways shifts would
/// fill the frame and every tick read the same rounded ε).
void set_epsilon_axis(std::string& commands, double eps_min, double eps_max);

/// Sideways offset of series `index` of `count` drawn at the same ε, so that their error bars do
/// not hide one another: a few thousandths of the panel's ε span, centred on zero.
double sideways_shift(std::size_t index, std::size_t count, double eps_min, double eps_max);

/// The canvas of a row of `panels` plots (at most three across): 800 px and 3.6 in per panel.
Canvas row_of_panels(std::size_t panels, int png_height = 760, double pdf_height = 3.4);

/// Light grid lines at the tics and short error-bar ends: panels full of error bars.
inline constexpr const char* k_light_grid_small_bars =
    "  set grid xtics ytics linecolor rgb '#dddddd'\n  set bars small\n";

/// Canvas and common settings of a row of `panels` plots against ε (Fig. 4, b(ε)).
void begin_epsilon_panels(FigureScript& script, std::size_t panels, const std::string& title,
                          const std::string& ylabel, const std::string& key_position);

}  // namespace molchaos::figures::detail
