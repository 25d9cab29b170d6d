// Renders the paper's figures (Fig. 3, Fig. 4, b(ε), a2(ε), a snapshot, the quadrature's
// work–precision diagram) from the plain data types of validation/ into PNG and PDF files with
// gnuplot. Next to every figure goes its gnuplot script with the data inline, so the figure can be
// re-plotted.
#pragma once

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "molchaos/validation/breakdown.hpp"
#include "molchaos/validation/correlation_tables.hpp"
#include "molchaos/validation/figure_data.hpp"
#include "molchaos/validation/flow_field.hpp"
#include "molchaos/validation/gas_fields.hpp"

namespace molchaos::figures {

struct RenderOptions {
  std::string output_directory;  ///< created if missing
  bool pdf = true;
  bool png = true;
  std::string gnuplot_executable = "gnuplot";  ///< looked up on PATH unless it contains a '/'
  /// Set (from a SIGINT or SIGTERM handler) to stop: the gnuplot under way is ended and waited
  /// for, the figure's temporaries are removed, and the render call throws Interrupted. Checked
  /// at least every 100 ms while gnuplot runs.
  const std::atomic<bool>* interrupt = nullptr;
};

/// A render call stopped by RenderOptions::interrupt; it left no file of its own behind.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The files a render call wrote, all complete: the images and the gnuplot script (`.gp`).
struct RenderedFigure {
  std::vector<std::string> files;
};

// Every render_* function throws std::invalid_argument naming the offending field when the data
// cannot be drawn (empty, mismatched vector lengths, non-positive values on a log axis), and
// std::runtime_error naming the file when gnuplot is missing or fails; on error it leaves no file
// of its own behind.

/// True when gnuplot runs and knows `terminal` (e.g. "gif", which some builds lack).
bool gnuplot_has_terminal(const std::string& terminal, const RenderOptions& options);

/// Fig. 3: T/T0 against ln t, every curve, the clustering onset marked, and an inset magnifying
/// inset_log_t_min ≤ ln t ≤ inset_log_t_max. Writes fig3_temperature.{png,pdf,gp}.
RenderedFigure render_fig3(const validation::Fig3Data& data, const RenderOptions& options);

/// Fig. 4: A(ε) = τ0(1 − ε²), one panel per density, error bars, linear fits, kinetic theory.
/// Writes fig4_A_of_eps.{png,pdf,gp}.
RenderedFigure render_fig4(const validation::Fig4Data& data, const RenderOptions& options);

/// b(ε), one panel per density, one point set per way of obtaining it.
/// Writes fig_b_of_eps.{png,pdf,gp}.
RenderedFigure render_b(const validation::BData& data, const RenderOptions& options);

/// a2(ε), one panel per density: every gas's points with error bars, the first-Sonine a2 (dashed)
/// and the improved a2 with a2² and a3 (solid). Writes fig_a2_of_eps.{png,pdf,gp}.
RenderedFigure render_a2(const validation::A2Data& data, const RenderOptions& options);

/// Particles coloured by speed with the coarse-grained velocity field as arrows.
/// Writes fig_snapshot.{png,pdf,gp}.
RenderedFigure render_snapshot(const validation::SnapshotData& data, const RenderOptions& options);

/// CPU time against the error reached (and its estimate), log–log, labelled by the requested
/// tolerance. Writes <basename>.{png,pdf,gp}.
RenderedFigure render_work_precision(const validation::WorkPrecisionData& data,
                                     const RenderOptions& options, const std::string& basename);

/// The file name, without extension, of render_simulation_cost's figure.
inline constexpr const char* k_simulation_cost_figure = "work_precision_simulation";
/// Relative standard error of A against CPU seconds, one line per N, targets dashed.
/// Writes k_simulation_cost_figure.{png,pdf,gp}.
RenderedFigure render_simulation_cost(const validation::SimulationWorkPrecisionData& data,
                                      const RenderOptions& options);

/// Coarse-grained velocity (arrows) over vorticity and the density field, per time and gas.
/// Writes fig_flow_field.{png,pdf,gp}.
RenderedFigure render_flow_field(const validation::FlowFieldData& data,
                                 const RenderOptions& options);

/// The flow-field figure as an animated GIF, one frame per row of `data` (a time), the gases
/// side by side; colour ranges per frame, one arrow scale for all. Writes fig_flow_field.gif and
/// its script fig_flow_field_animation.gp; needs gnuplot's gif terminal (gnuplot_has_terminal).
RenderedFigure render_flow_field_animation(const validation::FlowFieldData& data,
                                           const RenderOptions& options);

/// S⊥(k, τ) against linear hydrodynamics, and S⊥, S(k) of the largest modes against ln t for
/// the original and the randomized gases. Writes fig_structure_factor.{png,pdf,gp}.
RenderedFigure render_structure_factors(const std::vector<validation::StructureFactorCurve>& curves,
                                        const validation::GasFieldStudy& gases,
                                        const RenderOptions& options);

/// S⊥(k, τ) against linear hydrodynamics alone, one panel under `title` (the d = 3 set).
/// Writes <basename>.{png,pdf,gp}.
RenderedFigure render_linear_hydrodynamics(
    const std::vector<validation::StructureFactorCurve>& curves, const std::string& title,
    const std::string& basename, const RenderOptions& options);

/// G∥(r) and G⊥(r) of the original and the molecular-chaos gas at every stored time, one state
/// point. Writes fig_pair_correlations.{png,pdf,gp}.
RenderedFigure render_pair_correlations(const std::vector<validation::PairCorrelationRow>& rows,
                                        int dimension, double density, double restitution,
                                        const RenderOptions& options);

/// ⟨(c1·e)(c2·e)⟩ and ⟨c1·c2⟩ at contact against ε, one panel per (d, n).
/// Writes fig_contact_moments.{png,pdf,gp}.
RenderedFigure render_contact_moments(const std::vector<validation::ContactMomentRow>& rows,
                                      const RenderOptions& options);

/// The impact-parameter histogram's departure from flat, fraction·bins − 1, against s: original
/// and flux-shuffled gas, one curve per ε, one panel per (d, n). Writes
/// fig_impact_parameter.{png,pdf,gp}.
RenderedFigure render_impact_parameter(const std::vector<validation::ImpactParameterRow>& rows,
                                       const RenderOptions& options);

/// ln(A_orig/A_chaos) and its two factors (collision frequency, energy loss per collision)
/// against ε, one panel per (d, n). Writes fig_cooling_decomposition.{png,pdf,gp}.
RenderedFigure render_cooling_decomposition(
    const std::vector<validation::CoolingDecompositionRow>& rows, const RenderOptions& options);

}  // namespace molchaos::figures
