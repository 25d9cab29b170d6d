// REPORT.md and the CSVs of Fig. 4 and of a2(ε). The report leads with its findings (one line per
// claim), then the figures with their captions, then every comparison row and the tables behind the
// figures.
#include "molchaos/validation/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/theory/hydrodynamics.hpp"
#include "molchaos/theory/sonine.hpp"
#include "molchaos/validation/pair_correlations.hpp"
#include "molchaos/validation/verdict.hpp"
#include "reproduce_steps.hpp"

namespace molchaos::validation {

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::filesystem::path target(path);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  sim::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

std::string rerun_lines(const ReproduceConfig& config) {
  return fmt::format("# quick = {}\n# seeds = {}\n# base_seed = {}\n", config.quick, config.seeds,
                     config.base_seed);
}

std::string after_title(std::string csv, const std::string& lines) {
  csv.insert(csv.find('\n') + 1, lines);
  return csv;
}

namespace {

std::string header_lines(const ReproduceResults& r) {
  const auto& c = r.config;
  std::string s = fmt::format("# molchaos reproduce ({})\n{}# version = {}\n",
                              c.quick ? "quick" : "paper scale", rerun_lines(c), r.version);
  s += fmt::format("# dimension = 2\n# particles = {}\n", c.particles);
  s += fmt::format(
      "# t_end_in_tau0 = {}\n# samples_per_decade = {}\n# relax_collisions_per_particle = {}\n",
      c.t_end_in_tau0, r.fig4_spec.samples_per_decade, r.fig4_spec.relax_collisions_per_particle);
  s += window_rule_line(c.window);
  s += fmt::format(
      "# dsmc_seeds = {} (method = dsmc at every Fig. 4 point, mode none; the first stage, as "
      "seeds)\n",
      r.dsmc_spec.seeds);
  return s;
}

// Every point of Fig. 4 with the name of its gas: the MD modes, then DSMC ("dsmc", molecular
// chaos by construction).
std::vector<std::pair<const PointResult*, std::string>> fig4_rows(const ReproduceResults& r) {
  std::vector<std::pair<const PointResult*, std::string>> rows;
  for (const auto& p : r.fig4_points) rows.emplace_back(&p, p.summary.mode);
  for (const auto& p : r.dsmc_points) rows.emplace_back(&p, "dsmc");
  return rows;
}

std::string fmt_measurement(const std::optional<Measurement>& m) {
  if (!m) return "–";
  if (m->error == 0.0) return fmt::format("{:.6g}", m->value);
  return fmt::format("{:.6g} ± {:.2g}", m->value, m->error);
}

constexpr const char* k_not_decided = "not decided";

// A simulated value compared with another one (theory, DSMC, the paper's) that has no standard
// error to compare it by. A row of a χ² statistic (no value beside it) carries no error by design.
bool compared_without_standard_error(const ComparisonRow& row) {
  return row.simulation && !(row.simulation->error > 0.0) && (row.theory || row.paper);
}

std::string undecided_reason(std::size_t rows_without_error, std::size_t rows, int seeds) {
  if (seeds < 2)
    return fmt::format(
        "one seed per point gives no standard errors ({} of the {} compared values have none); "
        "two seeds or more decide it",
        rows_without_error, rows);
  return fmt::format(
      "{} of the {} compared values come from fewer than two runs and have no standard error",
      rows_without_error, rows);
}

}  // namespace

std::string with_error(double value, double error, int decimals) {
  if (!(error > 0.0) || !std::isfinite(error)) return fmt::format("{:.{}f}", value, decimals);
  return fmt::format("{:.{}f} ± {:.{}f}", value, decimals, error, decimals);
}

void withhold_undecidable_verdicts(std::vector<Claim>& claims, int seeds) {
  for (auto& claim : claims) {
    std::size_t without_error = 0;
    for (auto& row : claim.rows) {
      if (!compared_without_standard_error(row)) continue;
      ++without_error;
      row.verdict = k_not_decided;
      row.difference_in_se.reset();
    }
    if (without_error == 0) continue;
    claim.verdict = k_not_decided;
    claim.deciding = undecided_reason(without_error, claim.rows.size(), seeds);
  }
}

std::string fig4_csv(const ReproduceResults& r) {
  std::string s = header_lines(r);
  s += "density,restitution,randomize,A,A_err,runs,A_theory,A_theory_err,a2,a2_err,mean_dyad,mean_"
       "dyad_err,breakdowns\n";
  for (const auto& [point, mode] : fig4_rows(r)) {
    const PointResult& p = *point;
    const auto& m = p.summary;
    s += fmt::format("{},{},{},{:.10g},{:.4g},{},{:.10g},{:.3g},{:.6g},{:.3g},{:.8g},{:.3g},{}\n",
                     m.density, m.restitution, mode, m.A.value, error_of_runs(m.A.error, m.runs),
                     m.runs, p.A_theory.value, p.A_theory.error, m.a2.value,
                     error_of_runs(m.a2.error, m.runs), m.mean_dyad.value,
                     error_of_runs(m.mean_dyad.error, m.runs), m.breakdowns);
  }
  return s;
}

std::string fig4_fits_csv(const ReproduceResults& r) {
  std::string s = header_lines(r);
  s += "# A = intercept + slope * eps by weighted least squares over the points of a gas, errors "
       "scaled by sqrt(chi2/dof) where it exceeds 1; slope_err_over_seeds: the slope's standard "
       "error by the jackknife over seeds, scaled likewise (nan with one seed)\n";
  s += "density,randomize,intercept,intercept_err,slope,slope_err,chi2_per_dof,points,slope_err_"
       "over_seeds\n";
  for (const auto& panel : r.fig4.panels)
    for (const auto& series : panel.series)
      if (series.fit)
        s += fmt::format(
            "{},{},{:.10g},{:.4g},{:.10g},{:.4g},{:.4g},{},{:.4g}\n", panel.density, series.mode,
            series.fit->intercept, series.fit->intercept_error, series.fit->slope,
            series.fit->slope_error, series.fit->chi2_per_dof, series.points.size(),
            series.slope_error_over_seeds > 0 ? series.slope_error_over_seeds
                                              : std::numeric_limits<double>::quiet_NaN());
  return s;
}

std::string a2_csv(const ReproduceResults& r) {
  std::string s = header_lines(r);
  s += "# a2 of a gas (source none, paper, flux: MD; dsmc): mean ± standard error over runs of "
       "each run's a2 averaged over its Haff-fit window; first_sonine (Eq. (25)) and a2_a3 "
       "(with a2^2 and a3): the Sonine theory, a2_err its quadrature error\n";
  s += "dimension,density,restitution,source,a2,a2_err\n";
  const int d = r.a2.dimension;
  for (const auto& panel : r.a2.panels) {
    for (const auto& series : panel.series)
      for (std::size_t i = 0; i < series.a2.size(); ++i)
        s += fmt::format("{},{},{},{},{:.6g},{:.3g}\n", d, panel.density, series.restitution[i],
                         series.mode, series.a2[i].value,
                         error_of_runs(series.a2[i].error, series.runs[i]));
    for (std::size_t i = 0; i < panel.theory_restitution.size(); ++i) {
      const double e = panel.theory_restitution[i];
      s += fmt::format("{},{},{:.3f},first_sonine,{:.10g},{:.3g}\n", d, panel.density, e,
                       panel.first_sonine[i].value, panel.first_sonine[i].error);
      s += fmt::format("{},{},{:.3f},a2_a3,{:.10g},{:.3g}\n", d, panel.density, e,
                       panel.improved[i].value, panel.improved[i].error);
    }
  }
  return s;
}

namespace {

// The paper, by its published reference.
constexpr const char* k_paper_reference =
    "T. Pöschel, N. V. Brilliantov, T. Schwager, *Violation of molecular chaos in dissipative "
    "gases*, Int. J. Mod. Phys. C **13** (2002), doi:10.1142/S012918310200411X "
    "(arXiv:cond-mat/0210058)";

std::string summary_section(const ReproduceResults& r) {
  std::string s = "## Findings\n\n| | claim | verdict | decided by |\n|---|---|---|---|\n";
  int k = 0;
  for (const auto& c : r.claims)
    s += fmt::format("| {}{} | {} | **{}** | {} |\n",
                     c.source == ClaimSource::paper ? "paper " : "suite ", ++k, c.statement,
                     c.verdict, c.deciding);
  s += fmt::format(
      "\n*paper*: a claim of the paper; *suite*: a finding of this suite beyond it. Verdicts: "
      "*reproduced*, the suite's numbers agree with the claim by the rule below; *not "
      "reproduced*, its simulations disagree with a claim about simulated gases; *contradicted*, "
      "its exact computation differs from a formula or number the paper prints; *not decided*, "
      "its runs cannot tell (no standard errors, a box where the effect cannot arise, or a "
      "difference its errors do not resolve). Verdict rule "
      "(every row below): a number agrees with the one it is compared with when they differ by "
      "at most {:g} combined standard errors (theory: its quadrature error; simulation: the "
      "standard error over independent runs); each row names the rule it used. A claim over "
      "many points (a gas against theory or another gas at every ε) is decided by one global "
      "test, not point by point: each point's difference in standard errors, a Student t with "
      "runs − 1 degrees of freedom, is mapped to the normal score of the same tail probability, "
      "and the squares are summed to a χ² with one degree of freedom per point; where the "
      "errors are propagated from whole ensembles (b from cooling against b at contact) the χ² "
      "is the plain sum of the squared differences over their combined errors. The claim holds "
      "where p ≥ {:g} (the two-sided tail of {:g} standard errors).\n\n",
      k_agreement_standard_errors, k_global_p_threshold, k_agreement_standard_errors);
  return s;
}

std::string setup_section(const ReproduceResults& r, const std::string& command) {
  const auto& c = r.config;
  std::string s = "## Setup\n\n";
  s += fmt::format("Generated by `{}` (molchaos {}). {}\n\n", command, r.version,
                   c.quick ? "**Quick look**: small system and few seeds; use `make reproduce` for "
                             "the paper's scale."
                           : "Paper scale.");
  s += std::string("Paper: ") + k_paper_reference +
       ". Units σ = m = k_B = 1, T0 = 1, T = m⟨v²⟩/d, time in σ(m/T0)^½. Every simulated number "
       "is the mean over independent runs ± its standard error; every theory number carries "
       "its quadrature error estimate.\n\n";
  // The stages only when a target error asked for them (--quick runs its seeds alone).
  const double largest = steps::largest_relative_error_of_A(r);
  const std::string largest_text =
      largest > 0.0 ? fmt::format("{:.3f} %", 100.0 * largest) : "not measured (one run a point)";
  const std::string stages =
      c.target_relative_error > 0.0
          ? fmt::format(
                "Runs are then added in stages until the relative standard error of A reaches "
                "{:.2f} %: first as many as a smooth model of each gas's scatter per run over ε "
                "asks for, then more at any point still above the target (the runs column; the "
                "largest relative standard error left is {}).",
                100.0 * c.target_relative_error, largest_text)
          : fmt::format("No runs are added (the largest relative standard error of A is {}).",
                        largest_text);
  s += fmt::format(
      "d = 2, N = {}, densities {}, {} restitutions from {} to {}. Each point starts with {} "
      "runs, whose {} relaxed initial states are the same for every ε and gas at one density. "
      "{} Each run lasts {} kinetic-theory τ0; A comes from the integrated form of Haff's law "
      "over the run's window (the estimator finding below).\n\n"
      "The gases: `none`, the original inelastic gas; `paper`, the paper's shuffle (after each "
      "collision the pair takes the velocities of two particles drawn uniformly, in the order "
      "that makes it separate); `flux`, the flux-weighted shuffle (the donor pair drawn with "
      "weight |(v_k − v_l)·e|, the collision flux of a gas without correlations, so that an "
      "elastic gas stays in equilibrium); DSMC, the Enskog–Boltzmann equation solved by direct "
      "simulation Monte Carlo (velocities only, molecular chaos by construction).\n\n",
      c.particles, fmt::join(c.densities, ", "), c.restitutions.size(), c.restitutions.front(),
      c.restitutions.back(), c.seeds, c.seeds, stages, c.t_end_in_tau0);
  if (r.failed_runs > 0) {
    s += fmt::format("**{} run(s) failed**:\n\n", r.failed_runs);
    for (const auto& f : r.failures) s += "- " + f + "\n";
    s += "\n";
  }
  return s;
}

std::string verdict_table(const ReproduceResults& r) {
  std::string s =
      "## Every comparison\n\nEach row: theory (or the expected value) ± error, simulation ± "
      "error, the paper's printed value, the difference in combined standard errors, the "
      "verdict and the rule that gave it.\n\n| claim / quantity | theory | simulation | paper | "
      "diff [SE] | verdict | rule | note |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& claim : r.claims)
    for (const auto& row : claim.rows)
      s += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", row.quantity,
                       fmt_measurement(row.theory), fmt_measurement(row.simulation),
                       row.paper ? fmt::format("{:.6g}", *row.paper) : "–",
                       row.difference_in_se ? fmt::format("{:+.2f}", *row.difference_in_se) : "–",
                       row.verdict, row.rule, row.note);
  return s + "\n";
}

std::string fig4_tables(const ReproduceResults& r) {
  std::string s =
      "## Table behind Fig. 4: A(ε) = τ0(1 − ε²)\n\nA (theory) is kinetic theory's with b = 0; "
      "a2 (theory) is the first-Sonine a2(ε) (van Noije & Ernst), which that A uses.\n\n| n | ε "
      "| mode | A (sim) | runs | A (theory, b = 0) | diff [SE] | a2 (sim) | a2 (theory) "
      "|\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [point, mode] : fig4_rows(r)) {
    const PointResult& p = *point;
    const auto& m = p.summary;
    // One run gives no standard error, and a difference in standard errors needs one.
    const double se = std::hypot(error_of_runs(m.A.error, m.runs), p.A_theory.error);
    s += fmt::format(
        "| {} | {:.2f} | {} | {} | {} | {:.5f} | {} | {} | {:.4f} |\n", m.density, m.restitution,
        mode, with_error(m.A.value, error_of_runs(m.A.error, m.runs), 5), m.runs, p.A_theory.value,
        se > 0 ? fmt::format("{:+.2f}", (m.A.value - p.A_theory.value) / se) : "–",
        with_error(m.a2.value, error_of_runs(m.a2.error, m.runs), 4),
        theory::a2_first_sonine(m.dimension, m.restitution));
  }
  s += "\nLinear fits A = a + s·ε (weighted least squares, errors scaled by √(χ²/dof) where it "
       "exceeds 1; the last column is the slope's SE by the jackknife over seeds, which the ε "
       "points of a gas share):\n\n| n | mode | a | s | χ²/dof | SE(s) over seeds "
       "|\n|---|---|---|---|---|---|\n";
  for (const auto& panel : r.fig4.panels)
    for (const auto& series : panel.series)
      if (series.fit)
        s += fmt::format(
            "| {} | {} | {:.4f} ± {:.4f} | {:.4f} ± {:.4f} | {:.2f} | {} |\n", panel.density,
            series.mode, series.fit->intercept, series.fit->intercept_error, series.fit->slope,
            series.fit->slope_error, series.fit->chi2_per_dof,
            series.slope_error_over_seeds > 0 ? fmt::format("{:.4f}", series.slope_error_over_seeds)
                                              : "–");
  return s;
}

std::string b_table(const ReproduceResults& r) {
  std::string s =
      "\n## Table behind the b(ε) figure\n\n| n | method | ε | b |\n|---|---|---|---|\n";
  for (const auto& panel : r.b.panels)
    for (const auto& series : panel.series)
      for (std::size_t i = 0; i < series.b.size(); ++i)
        s +=
            fmt::format("| {} | {} | {:.2f} | {} |\n", panel.density, series.label,
                        series.restitution[i], with_error(series.b[i].value, series.b[i].error, 5));
  return s;
}

std::string fig3_table(const ReproduceResults& r) {
  const auto& c = r.config;
  const auto& o = r.fig3_original.summary;
  std::string s = "\n## Table behind Fig. 3\n\n";
  const std::string onset =
      o.breakdowns == 0
          ? std::string("no break-down detected before t_end")
          : fmt::format("break-down detected in {} runs at ln t_b = {} (mean of ln t_b; t_b = {})",
                        o.breakdowns,
                        with_error(o.log_breakdown_time.value,
                                   error_of_runs(o.log_breakdown_time.error, o.breakdowns), 2),
                        with_error(o.breakdown_time.value,
                                   error_of_runs(o.breakdown_time.error, o.breakdowns), 1));
  s += fmt::format("Original gas at ε = {}, n = {}: A = {} ({} runs); {}.\n\n", c.fig3_restitution,
                   c.fig3_density, with_error(o.A.value, error_of_runs(o.A.error, o.runs), 5),
                   o.runs, onset);
  s += "| ln t |";
  for (const auto& curve : r.fig3.curves) s += " " + curve.label + " |";
  s += "\n|---|";
  for (std::size_t k = 0; k < r.fig3.curves.size(); ++k) s += "---|";
  s += "\n";
  if (!r.fig3.curves.empty()) {
    const auto& t = r.fig3.curves.front().t;
    for (std::size_t i = 0; i < t.size(); i += 4) {
      s += fmt::format("| {:.3f} |", std::log(t[i]));
      for (const auto& curve : r.fig3.curves) {
        if (i >= curve.T.size()) {
          s += " – |";
          continue;
        }
        // The simulated gases with their standard error over runs (the bands of the figure);
        // Haff's-law lines and single runs without one.
        const double error = i < curve.T_error.size() ? curve.T_error[i] : 0.0;
        s += error > 0.0 ? fmt::format(" {:.6g} ± {:.2g} |", curve.T[i], error)
                         : fmt::format(" {:.6g} |", curve.T[i]);
      }
      s += "\n";
    }
  }
  return s;
}

}  // namespace

std::string figure_caption(const std::string& file, const ReproduceResults& r) {
  const auto& c = r.config;
  if (file.starts_with("fig3_temperature"))
    return fmt::format(
        "Fig. 3: temperature T/T0 against ln t at ε = {}, n = {} for the original gas and the two "
        "randomized gases, with Haff's law (dashed); the lower panel shows each gas's relative "
        "deviation T/T_Haff − 1 from Haff's law with kinetic theory's τ0 (solid) and with its "
        "own fitted τ0 (dashed), bands one standard error over runs. Look at the lower panel: "
        "a gas that cools by Haff's law with kinetic theory's τ0 stays on zero within its "
        "band{}",
        c.fig3_restitution, c.fig3_density,
        r.fig3_original.summary.breakdowns > 0
            ? "; the dotted vertical line marks the detected clustering onset of the original "
              "gas (the mean of ln t_b over the runs that broke down)."
            : " (no run broke down before t_end: no onset is marked).");
  if (file.starts_with("fig4_A_of_eps"))
    return "Fig. 4: A = τ0(1 − ε²) against ε, one panel per density, mean ± standard error over "
           "runs of each gas (the MD gases and DSMC, the molecular-chaos reference) with weighted "
           "straight-line fits (solid) and kinetic theory (b = 0, dashed black line). Look at the "
           "slopes of the original gas against the nearly flat kinetic theory, and at where each "
           "randomized gas lies relative to the theory line and to DSMC.";
  if (file.starts_with("fig_b_of_eps"))
    return "b(ε), the velocity correlation at contact, obtained three ways: from the cooling "
           "rates of the original and the flux-shuffled gas (with the paper's coefficients and "
           "with the suite's), and directly from the velocities at contact, less the DSMC gas's "
           "(molecular chaos, with the Sonine terms beyond a2 that the inversion leaves out); the "
           "flux gas's contact b, less the DSMC gas's, is the control and should be zero. Look "
           "whether the cooling-rate and contact values agree.";
  if (file.starts_with("fig_impact_parameter"))
    return "Impact parameter s of the colliding pairs (0 head-on, 1 grazing) as the departure of "
           "its histogram from flat, fraction · bins − 1, one panel per dimension and density, "
           "each bin the inverse-variance mean over the panel's restitutions (each ε alone: "
           "`impact_parameter.csv`; filled, solid: original gas; open, dashed: flux-shuffled "
           "gas). Molecular chaos makes every bin zero; look at the last bin (grazing "
           "collisions) of the original gas against the flux gas.";
  if (file.starts_with("fig_a2_of_eps"))
    return "a2(ε), the second Sonine coefficient, one panel per density: the original, the "
           "paper-shuffled, the flux-shuffled and the DSMC gas (mean ± standard error over runs "
           "of the a2 averaged over the Haff-fit window), the first-Sonine a2 the paper quotes "
           "(Eq. (25), dashed) and the improved a2 with a2² and a3 (solid). Look at which line "
           "the DSMC circles follow where the two lines part (small ε), and whether the MD gases' "
           "a2 lies on the DSMC gas's.";
  if (file.starts_with("fig_snapshot"))
    return fmt::format(
        "Snapshot of the original gas at the end of Fig. 3's runs ({}), ε = {}, n = {}: "
        "particles coloured by speed over the rms speed, arrows the coarse-grained velocity "
        "field. Look at whether the density is still uniform and whether neighbouring arrows "
        "align (clusters and vortices).",
        r.fig3_original.summary.breakdowns > 0
            ? "after the detected break-down of the homogeneous state, which the velocity field "
              "shows before the density: clusters are still faint at this time"
            : "no break-down detected before it",
        c.fig3_restitution, c.fig3_density);
  if (file.starts_with("fig_pair_correlations"))
    return "Velocity correlations of pairs at separation r, at the state point of the title: "
           "G∥(r) = ⟨(c1·r̂)(c2·r̂)⟩ (left) and G⊥(r) = ⟨c1·c2 − (c1·r̂)(c2·r̂)⟩/(d − 1) (right), "
           "c = v/√(2T), at the collisions per particle τ of the key, for the original gas "
           "(filled, solid) and the flux-shuffled gas (open, dashed); error bars one standard "
           "error of the pair averages. Molecular chaos makes both zero at every r. Look at how "
           "far out the original gas's correlations reach, and at their sign.";
  if (file.starts_with("fig_contact_moments"))
    return "Collision averages of the reduced pre-collision velocities c = v/√(2T) against ε, "
           "⟨(c1·e)(c2·e)⟩ (blue) and ⟨c1·c2⟩ (orange), mean ± standard error over runs, one "
           "panel per dimension and density: the original gas (filled) and the two "
           "molecular-chaos references, the flux-shuffled gas and the DSMC gas (open). Under "
           "molecular chaos both equal −1/4 + a2/16 (dashed: a2 = 0). Look at how far above it "
           "the original gas lies, and at the gap between its two averages: its transverse "
           "velocity correlation at contact, zero under molecular chaos.";
  if (file.starts_with("fig_cooling_decomposition"))
    return "The cooling rate of the original gas against the flux-shuffled gas (molecular "
           "chaos), paired by seed, mean ± standard error over the pairs, one panel per "
           "dimension and density: ln(A_orig/A_chaos) from the Haff fits, and its two factors, "
           "ln(ω_chaos/ω_orig) from the collision frequencies and ln(Y_chaos/Y_orig) from the "
           "energy lost per collision, Y = ⟨(v12·e)²⟩/(4T). The cooling rate is the product of "
           "the two, so the first series should equal the sum of the other two. Look at "
           "which factor carries the original gas's slower cooling.";
  if (file.starts_with("fig_structure_factor") && !file.starts_with("fig_structure_factor_3d"))
    return fmt::format(
        "Break-down of the homogeneous cooling state, ε = {}, n = {}: left, S⊥(k, τ) of the "
        "largest shear modes of the original gas in the two boxes of the key, run mean ± "
        "standard error (points), against linear hydrodynamics with no free parameter (lines); "
        "middle and right, S⊥ and the density structure factor S of the largest modes against "
        "ln t for the original gas and the two shuffled gases (1: no structure). Look at the "
        "vortices that grow as predicted in the original gas, the density that follows, and "
        "the shuffled gases that stay at 1.",
        r.gas_fields.spec.restitution, r.gas_fields.spec.density);
  if (file.starts_with("fig_flow_field"))
    return fmt::format(
        "Flow and density fields of the original gas and the randomized gases (ε = {}, n = {}, "
        "N = {}), built from the Fourier modes |m|² ≤ {} of one run each: the vorticity in units "
        "of its standard deviation in a gas without correlations (colour, one range for all "
        "panels), the mean velocity as arrows, and contours where the density lies 2 such units "
        "above its mean (solid) or below it (dashed). A gas without correlations stays within "
        "about ±3 of them; look for the vortices that grow beyond that in the original gas and "
        "the dense patches that follow, and for any structure in the shuffled gases.",
        r.gas_fields.spec.restitution, r.gas_fields.spec.density, r.gas_fields.spec.particles,
        r.gas_fields.spec.field_max_norm2);
  if (file.starts_with("fig_structure_factor_3d")) {
    const auto spec = BreakdownSpec::three_dimensional();
    const auto hydro = theory::transport_coefficients({3, spec.density, spec.restitution, {}});
    const auto paper_like =
        theory::transport_coefficients({3, c.fig3_density, c.fig3_restitution, {}});
    const double paper_box = theory::critical_box_size(paper_like);
    return fmt::format(
        "Linear hydrodynamics in d = 3 (ε = {}, n = {}): S⊥(k, τ) of the largest shear modes, "
        "run mean ± standard error over {} runs (points), against the prediction with no free "
        "parameter (lines), in a box of N = {} above L_c and one of N = {} below it. The state "
        "point is the theory's choice: there L_c = 2π/k⊥ = {:.1f}σ and the heat mode's 2π/k∥ = "
        "{:.1f}σ (`molchaos theory --dim 3 --restitution {} --density {} --particles {}`), so the "
        "large box ({:.1f}σ) has only growing shear modes and the small one ({:.1f}σ) none; at "
        "the paper's ε = {}, n = {}, L_c = {:.0f}σ, and a box above it holds more than {:.0f} "
        "spheres. Look "
        "at the growth in the large box and the saturation below L_c.",
        spec.restitution, spec.density, spec.runs, spec.unstable_particles, spec.stable_particles,
        theory::critical_box_size(hydro), 2 * M_PI / theory::critical_heat_wavenumber(hydro),
        spec.restitution, spec.density, spec.unstable_particles,
        std::cbrt(static_cast<double>(spec.unstable_particles) / spec.density),
        std::cbrt(static_cast<double>(spec.stable_particles) / spec.density), c.fig3_restitution,
        c.fig3_density, paper_box, c.fig3_density * paper_box * paper_box * paper_box);
  }
  return "";
}

namespace {

// The flow-field animation beside the still figure, or why there is none.
std::string animation_line(const ReproduceResults& r, const std::vector<std::string>& figures) {
  if (std::find(figures.begin(), figures.end(), "fig_flow_field.gif") == figures.end())
    return "Animation: not made, gnuplot on this machine has no gif terminal.\n\n";
  const auto& frames = r.gas_fields.animation.rows;
  return fmt::format(
      "Animation of the same fields, original gas beside the flux-shuffled gas, {} frames from "
      "ln t = {:.3g} to {:.3g} (the first run of each gas):\n\n"
      "![fig_flow_field.gif](fig_flow_field.gif)\n\n",
      frames.size(), frames.empty() ? 0.0 : animation_log_times(r.gas_fields.spec).front(),
      frames.empty() ? 0.0 : animation_log_times(r.gas_fields.spec).back());
}

// The paper's central question in one paragraph: does one number b describe the two-particle
// distribution at contact? Its two routes to b, and the two-amplitude form's, from the
// correlation study's global tests, and whether those two amplitudes fit every contact moment.
std::string two_routes_headline(const CorrelationStudy& c) {
  if (c.b_routes.points == 0) return "";
  const double p = chi_square_p_value(c.two_amplitude_chi2, c.two_amplitude_dof);
  // Which state points: the correlation study's, in both dimensions (the Fig. 4 ensemble's own
  // comparison of the two routes is a row of the findings).
  int in_two = 0, in_three = 0;
  for (const auto& f : c.ansatz) ++(f.dimension == 2 ? in_two : in_three);
  const std::string points =
      in_two + in_three == c.b_routes.points
          ? fmt::format(
                " The state points are the correlation study's, {} in d = 2 and {} in "
                "d = 3 (each point's paired routes and fits: `ansatz_fits.csv`); the Fig. 4 "
                "ensemble compares the two routes in its own row below.",
                in_two, in_three)
          : std::string();
  return fmt::format(
      "**b, the velocity correlation of the paper's two-particle distribution at contact (its "
      "Eq. (14)), measured two ways by this suite** (the paper gives no measured b).{}\n\n"
      "- The printed ansatz, one b: {}\n"
      "- One amplitude for the longitudinal and one for the transverse velocity correlation at "
      "contact, in place of the printed dyad: {} The same two amplitudes fitted to all four "
      "contact moments at once give chi2 = {:.1f} for {} dof (p = {:.2g}): {}.\n\n",
      points, c.b_routes.statement, c.beta_par_routes.statement, c.two_amplitude_chi2,
      c.two_amplitude_dof, p,
      p >= k_global_p_threshold ? "they fit" : "they do not fit; closer than one b, not right");
}

}  // namespace

std::string report_markdown(const ReproduceResults& r, const std::vector<std::string>& figures,
                            const std::string& command) {
  std::string s = "# molchaos: reproduction report\n\n";
  s += fmt::format("molchaos {} reproduces {}{}.\n\n", r.version, k_paper_reference,
                   r.config.quick ? " (**quick look**, not the paper's scale)" : "");
  s += two_routes_headline(r.correlations);
  s += summary_section(r);
  s += setup_section(r, command);
  // Without figures (--no-figures, or no gnuplot) no empty section: the tables follow.
  if (!figures.empty()) s += "## Figures\n\n";
  for (const auto& f : figures) {
    if (f.ends_with(".gif")) continue;  // linked beside its still figure
    s += fmt::format("![{}]({})\n\n", f, f);
    const std::string caption = figure_caption(f, r);
    if (!caption.empty()) s += "*" + caption + "*\n\n";
    if (f == "fig_flow_field.png") s += animation_line(r, figures);
  }
  s += verdict_table(r);
  s += fig4_tables(r);
  s += b_table(r);
  s += fig3_table(r);
  s += "\n## Kinetic theory: μ2/μ2(0,0) coefficients (d = 2, printed dyad 3·ee − U)\n\n| term | "
       "computed | error |\n|---|---|---|\n";
  for (const auto& t : r.coefficients.terms)
    s += fmt::format("| {} | {:.12f} | {:.1e} |\n", t.name, t.coefficient.value,
                     t.coefficient.error);
  s += "\n## Parameters\n\n```\n" + header_lines(r) + "```\n";
  return s;
}

}  // namespace molchaos::validation
