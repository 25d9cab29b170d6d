// The figure steps of the reproduction: the data behind Fig. 4, b(ε), a2(ε), Fig. 3 and the
// snapshot, each computed from the ensembles once. Claims (reproduce_claims.cpp) read these data.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "molchaos/sim/run.hpp"
#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/paper_constants.hpp"
#include "molchaos/theory/sonine.hpp"
#include "molchaos/theory/sonine_hcs.hpp"
#include "molchaos/validation/shared_seed_fit.hpp"
#include "reproduce_steps.hpp"

namespace molchaos::validation::steps {
namespace {

constexpr int k_dimension = 2;

// The point of one gas at (n, ε): `mode` is a randomization's name, or "dsmc" for the DSMC
// ensemble.
const PointResult& gas_point(const ReproduceResults& R, double n, double e,
                             const std::string& mode) {
  return mode == "dsmc" ? find_dsmc_point(R, n, e) : find_point(R, n, e, mode);
}

// Every gas of Figs. 4 and a2(ε): the MD modes, then DSMC.
std::vector<std::string> gas_modes() {
  std::vector<std::string> modes;
  for (auto mode : k_modes) modes.emplace_back(sim::to_string(mode));
  modes.emplace_back("dsmc");
  return modes;
}

// One series of Fig. 4: A(ε) of an ensemble's points at density n, with its straight-line fit.
ASeries a_series(const ReproduceResults& R, double n, const std::string& mode) {
  ASeries s;
  s.mode = mode;
  s.label = mode_label(s.mode);
  std::vector<double> x;
  std::vector<Measurement> y;
  std::vector<const PointSummary*> summaries;
  for (double e : R.config.restitutions) {
    const auto& p = gas_point(R, n, e, mode);
    if (p.summary.runs == 0) continue;
    s.points.push_back({e, p.summary.A, p.summary.runs});
    x.push_back(e);
    y.push_back(p.summary.A);
    summaries.push_back(&p.summary);
  }
  if (x.size() < 2) return s;
  s.fit = fit_line(x, y);
  if (const auto error = slope_error_over_shared_seeds(x, summaries))
    s.slope_error_over_seeds = *error * std::sqrt(std::max(1.0, s.fit->chi2_per_dof));
  return s;
}

}  // namespace

void figure_fig4(ReproduceResults& R) {
  const auto& cfg = R.config;
  R.fig4.title = fmt::format("A(ε) = τ0 (1 − ε^2), N = {}", cfg.particles);
  for (double n : cfg.densities) {
    Fig4Panel panel;
    panel.density = n;
    for (const std::string& mode : gas_modes()) panel.series.push_back(a_series(R, n, mode));
    // Kinetic theory, b = 0: A = 1/(ω0 μ2/μ2(0,0)) with the first-Sonine a2(ε).
    for (double e = cfg.restitutions.front(); e <= cfg.restitutions.back() + 1e-9; e += 0.005) {
      panel.theory_restitution.push_back(e);
      const double a2 = theory::a2_first_sonine(k_dimension, e);
      panel.theory_A.push_back(1.0 / (theory::cooling_frequency_omega0(k_dimension, n, 1.0) *
                                      R.coefficients.ratio(a2, 0.0)));
    }
    R.fig4.panels.push_back(panel);
  }
}

namespace {

// a2(ε) of one gas at density n: each point's a2 (mean ± SE over runs of the window average).
A2Series a2_series(const ReproduceResults& R, double n, const std::string& mode) {
  A2Series s{mode_label(mode), mode, {}, {}, {}};
  for (double e : R.config.restitutions) {
    const auto& p = gas_point(R, n, e, mode);
    if (p.summary.runs == 0) continue;
    s.restitution.push_back(e);
    s.a2.push_back(p.summary.a2);
    s.runs.push_back(p.summary.runs);
  }
  return s;
}

}  // namespace

// The gases' a2 against the first-Sonine a2 the paper quotes (Eq. (25)) and the improved a2
// (a2² and a3, theory/sonine_hcs.hpp); the theory does not depend on the density.
void figure_a2(ReproduceResults& R) {
  const auto& cfg = R.config;
  R.a2.title = fmt::format("Sonine coefficient a2(ε), d = {}, N = {}", k_dimension, cfg.particles);
  R.a2.dimension = k_dimension;
  A2Panel theory_grid;
  for (double e = cfg.restitutions.front(); e <= cfg.restitutions.back() + 1e-9; e += 0.005) {
    const theory::HcsSonine levels = theory::hcs_sonine_coefficients(k_dimension, e);
    theory_grid.theory_restitution.push_back(e);
    theory_grid.first_sonine.push_back(levels.first_sonine.a2);
    theory_grid.improved.push_back(levels.a2_a3.a2);
  }
  for (double n : cfg.densities) {
    A2Panel panel = theory_grid;
    panel.density = n;
    for (const std::string& mode : gas_modes()) panel.series.push_back(a2_series(R, n, mode));
    R.a2.panels.push_back(std::move(panel));
  }
}

namespace {

// b from the cooling rates of the original and the flux gas, as independent means (the gases get
// their seeds apart; their weak positive correlation over common seeds makes these errors slightly
// conservative): with the paper's
// linear coefficient 63/40 and its ω0 (3D prefactor), and with the suite's full coefficients.
// R(a2, b) = R0(a2) + b·cb(a2) and A ∝ 1/R give b = R0 (A_rand/A − 1)/cb.
void b_from_cooling(const ReproduceResults& R, double n, double e, BSeries& paper_way,
                    BSeries& suite_way) {
  const auto& orig = find_point(R, n, e, "none");
  const auto& rand = find_point(R, n, e, "flux");
  if (orig.summary.runs == 0 || rand.summary.runs == 0) return;
  const double g2 = theory::contact_value_g2_at_density(k_dimension, n);
  const double omega0_paper =
      theory::k_paper_omega0_prefactor * g2 * n * std::sqrt(std::numbers::pi);
  const Measurement& Ao = orig.summary.A;
  const Measurement& Ar = rand.summary.A;
  const Measurement diff{Ao.value - Ar.value, std::hypot(Ao.error, Ar.error)};
  paper_way.restitution.push_back(e);
  const double coefficient_b = -theory::k_paper_coefficient_b;
  paper_way.b.push_back(
      {diff.value * omega0_paper / coefficient_b, diff.error * omega0_paper / coefficient_b});
  const double a2 = theory::a2_first_sonine(k_dimension, e);
  const double R0 = mu2_ratio_at_b0(R.coefficients, a2);
  const double cb = mu2_ratio_b_slope(R.coefficients, a2);
  const double r = Ar.value / Ao.value;
  const Measurement ratio{r, r * std::hypot(Ar.error / Ar.value, Ao.error / Ao.value)};
  suite_way.restitution.push_back(e);
  suite_way.b.push_back({R0 * (ratio.value - 1.0) / cb, R0 * ratio.error / std::abs(cb)});
}

// b of one gas from its pre-collision velocities at contact (mean dyad), inverted with its own
// a2 and a3 = 0; none where the dyad has no error bar (one run).
std::optional<Measurement> b_at_contact(const PointResult& p) {
  if (p.summary.mean_dyad.error <= 0) return std::nullopt;
  theory::QuadratureOptions quad;
  quad.relative_tolerance = 1e-10;
  const auto J =
      theory::contact_integrals(k_dimension, p.summary.a2.value, theory::k_paper_dyad_factor, quad);
  const auto b = J.b_from_mean_dyad(p.summary.mean_dyad.value, p.summary.mean_dyad.error);
  return Measurement{b.value, b.error};
}

// b directly from the velocities at contact, less the same inversion of the DSMC gas at the
// point (`chaos`). The inversion takes molecular chaos to be the Sonine form in a2 alone and
// leaves out the dyad's a3 term, 3a3/64 (doc/validation.md): with kinetic theory's a3 = −0.0105
// at ε = 0.8 a shift of b by −3e-4, up to a third of the original gas's b at n = 0.05. The DSMC
// gas is molecular chaos with every Sonine term, so the difference cancels it, as the cooling
// route cancels its own by taking the flux gas for molecular chaos.
void b_from_contacts(const PointResult& p, const std::optional<Measurement>& chaos, double e,
                     BSeries& series) {
  const std::optional<Measurement> b = b_at_contact(p);
  if (!b || !chaos) return;
  series.restitution.push_back(e);
  series.b.push_back({b->value - chaos->value, std::hypot(b->error, chaos->error)});
}

}  // namespace

void figure_b(ReproduceResults& R) {
  R.b.title = "velocity-correlation coefficient b(ε)";
  for (double n : R.config.densities) {
    BPanel bp;
    bp.density = n;
    BSeries b_paper{"from A, paper's 63/40 and ω0 (its 1/3)", {}, {}};
    BSeries b_suite{"from A, suite's coefficients and ω0", {}, {}};
    BSeries b_contact{"contacts, original gas − DSMC", {}, {}};
    BSeries b_control{"contacts, flux gas − DSMC (control)", {}, {}};
    for (double e : R.config.restitutions) {
      b_from_cooling(R, n, e, b_paper, b_suite);
      const std::optional<Measurement> b_chaos = b_at_contact(find_dsmc_point(R, n, e));
      b_from_contacts(find_point(R, n, e, "none"), b_chaos, e, b_contact);
      b_from_contacts(find_point(R, n, e, "flux"), b_chaos, e, b_control);
    }
    bp.series = {b_paper, b_suite, b_contact, b_control};
    R.b.panels.push_back(bp);
  }
}

namespace {

// Ensemble mean and standard error of T at each sample of the runs (common time grid), t ≥ 1.
TemperatureCurve mean_curve(const std::vector<const sim::RunResult*>& runs,
                            const std::string& label) {
  TemperatureCurve c;
  c.label = label;
  if (runs.empty()) return c;
  std::size_t len = runs.front()->samples.size();
  for (const auto* r : runs) len = std::min(len, r->samples.size());
  for (std::size_t i = 0; i < len; ++i) {
    const double t = runs.front()->samples[i].t;
    if (t < 1.0) continue;  // Fig. 3 starts at ln t = 0, as the paper's
    std::vector<double> T;
    for (const auto* r : runs) T.push_back(r->samples[i].temperature);
    const Measurement m = mean_and_standard_error(T);
    c.t.push_back(t);
    c.T.push_back(m.value);
    c.T_error.push_back(m.error);
  }
  return c;
}

TemperatureCurve haff_curve(double tau0, const std::vector<double>& times,
                            const std::string& label) {
  TemperatureCurve c;
  c.label = label;
  c.is_theory = true;
  for (double t : times) {
    c.t.push_back(t);
    c.T.push_back(theory::haff_temperature(t, 1.0, tau0));
    c.T_error.push_back(0.0);
  }
  return c;
}

// T/T_Haff − 1 of one gas's mean curve; the band is the standard error over runs.
TemperatureCurve deviation_curve(const TemperatureCurve& gas, double tau0, bool from_theory,
                                 const std::string& label) {
  TemperatureCurve d;
  d.label = label;
  d.is_theory = from_theory;
  for (std::size_t i = 0; i < gas.t.size(); ++i) {
    const double haff = theory::haff_temperature(gas.t[i], 1.0, tau0);
    d.t.push_back(gas.t[i]);
    d.T.push_back(gas.T[i] / haff - 1.0);
    d.T_error.push_back(gas.T_error[i] / haff);
  }
  return d;
}

// Fig. 3 needs a curve of every gas. A gas without one (every run failed, or no sample at t ≥ 1)
// stops the reproduction with the cause, instead of an empty curve the renderer cannot place.
void require_every_curve(const ReproduceResults& R, const std::vector<TemperatureCurve>& gases) {
  // A failed outcome holds no parameters: its mode is that of the run at its place in the spec.
  const auto runs = expand(R.fig3_spec);
  std::vector<std::string> missing, errors;
  for (std::size_t k = 0; k < gases.size(); ++k) {
    if (!gases[k].t.empty()) continue;
    missing.push_back(std::string(sim::to_string(k_modes[k])));
    for (std::size_t j = 0; j < R.fig3_runs.size() && j < runs.size(); ++j)
      if (!R.fig3_runs[j].ok && runs[j].randomize == k_modes[k])
        errors.push_back(R.fig3_runs[j].error);
  }
  if (missing.empty()) return;
  if (errors.empty())
    throw std::runtime_error(fmt::format(
        "Fig. 3 cannot be drawn: the runs of randomize = {} have no sample at t >= 1 (t_end = {})",
        fmt::join(missing, ", "), R.config.fig3_t_end));
  // Every failure is on stderr already; the first few name the cause in the one-line message.
  constexpr std::size_t k_listed = 3;
  const std::size_t listed = std::min(errors.size(), k_listed);
  throw std::runtime_error(fmt::format(
      "Fig. 3 cannot be drawn: no run of randomize = {} succeeded ({} failed): {}{}",
      fmt::join(missing, ", "), errors.size(),
      fmt::join(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(listed), "; "),
      errors.size() > listed ? fmt::format("; and {} more", errors.size() - listed) : ""));
}

}  // namespace

void figure_fig3(ReproduceResults& R) {
  const auto& cfg = R.config;
  R.fig3.title = fmt::format("T(t), ε = {}, n = {}, N = {}", cfg.fig3_restitution, cfg.fig3_density,
                             cfg.particles);
  const double tau0_theory = theory_tau0(k_dimension, cfg.fig3_density, cfg.fig3_restitution);
  const double one_minus = 1.0 - cfg.fig3_restitution * cfg.fig3_restitution;
  std::vector<TemperatureCurve> gases;
  for (auto mode : k_modes) {
    std::vector<const sim::RunResult*> group;
    for (const auto& o : R.fig3_runs)
      if (o.ok && o.result.parameters.randomize == mode) group.push_back(&o.result);
    const std::string name(sim::to_string(mode));
    gases.push_back(mean_curve(group, mode_label(name)));
    gases.back().mode = name;
  }
  require_every_curve(R, gases);
  const std::vector<double> times = gases.front().t;
  R.fig3.curves = gases;
  R.fig3.curves.push_back(haff_curve(
      tau0_theory, times, fmt::format("Haff's law, kinetic-theory τ0 = {:.2f}", tau0_theory)));
  // Haff's law with τ0 fitted to the flux-shuffled and to the original gas (as before).
  for (std::size_t i : {std::size_t{2}, std::size_t{0}}) {
    const auto& s = R.fig3_points.at(i).summary;
    if (s.runs == 0) continue;
    const double tau_fit = s.A.value / one_minus;
    R.fig3.curves.push_back(
        haff_curve(tau_fit, times,
                   fmt::format("Haff's law, τ0 fitted to the {} gas = {:.2f}",
                               i == 0 ? "original" : "flux-shuffled", tau_fit)));
  }
  for (std::size_t i = 0; i < gases.size(); ++i) {
    if (gases[i].t.empty()) continue;
    const auto& s = R.fig3_points.at(i).summary;
    R.fig3.deviations.push_back(
        deviation_curve(gases[i], tau0_theory, true, gases[i].label + ", kinetic-theory τ0"));
    if (s.runs > 0)
      R.fig3.deviations.push_back(deviation_curve(gases[i], s.A.value / one_minus, false,
                                                  gases[i].label + ", own fitted τ0"));
  }
  if (R.fig3_original.summary.breakdowns > 0)
    R.fig3.clustering_onset = std::exp(R.fig3_original.summary.log_breakdown_time.value);
}

namespace {

SnapshotData make_snapshot(const sim::Snapshot& snap, int grid) {
  SnapshotData s;
  s.time = snap.t;
  s.box = snap.box;
  const std::size_t n = snap.positions.size() / 2;
  double v2 = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    v2 += snap.velocities[2 * i] * snap.velocities[2 * i] +
          snap.velocities[2 * i + 1] * snap.velocities[2 * i + 1];
  const double vrms = std::sqrt(v2 / static_cast<double>(n));
  std::vector<double> sx(grid * grid, 0.0), sy(grid * grid, 0.0), count(grid * grid, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = snap.positions[2 * i], y = snap.positions[2 * i + 1];
    const double vx = snap.velocities[2 * i] / vrms, vy = snap.velocities[2 * i + 1] / vrms;
    s.x.push_back(x);
    s.y.push_back(y);
    s.speed.push_back(std::hypot(vx, vy));
    const int cx = std::min(grid - 1, static_cast<int>(x / snap.box * grid));
    const int cy = std::min(grid - 1, static_cast<int>(y / snap.box * grid));
    sx[cy * grid + cx] += vx;
    sy[cy * grid + cx] += vy;
    count[cy * grid + cx] += 1.0;
  }
  const double cell = snap.box / grid;
  for (int cy = 0; cy < grid; ++cy)
    for (int cx = 0; cx < grid; ++cx) {
      const int k = cy * grid + cx;
      if (count[k] == 0) continue;
      s.grid_x.push_back((cx + 0.5) * cell);
      s.grid_y.push_back((cy + 0.5) * cell);
      s.grid_vx.push_back(sx[k] / count[k]);
      s.grid_vy.push_back(sy[k] / count[k]);
    }
  return s;
}

}  // namespace

// The original gas (first seed) re-run to the end of Fig. 3, well after the clustering onset.
void figure_snapshot(ReproduceResults& R) {
  const auto& cfg = R.config;
  sim::Parameters p = expand(R.fig3_spec).at(0);
  p.snapshot_times = {cfg.fig3_t_end};
  p.t_end = cfg.fig3_t_end;
  p.contact_statistics = false;
  const sim::RunResult r = sim::run(p);
  if (r.snapshots.empty()) return;
  R.snapshot = make_snapshot(r.snapshots.back(), 10);
  R.snapshot.title =
      fmt::format("original gas at t = {:.0f} (ln t = {:.2f}), ε = {}, n = {}", R.snapshot.time,
                  std::log(R.snapshot.time), cfg.fig3_restitution, cfg.fig3_density);
}

}  // namespace molchaos::validation::steps
