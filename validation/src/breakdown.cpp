// Break-down of the homogeneous cooling state: linear hydrodynamics against simulation (see the
// header). Growth rates are slopes of ln S⊥(τ) of the run average against collisions per particle
// τ = 2·collisions/N, compared with the same slope of the predicted S⊥(τ) at the same τ; errors are
// jackknife errors over the independent runs.
#include "molchaos/validation/breakdown.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

#include "molchaos/sim/result.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/hydrodynamics.hpp"
#include "molchaos/validation/haff_fit.hpp"
#include "molchaos/validation/hcs_window.hpp"
#include "molchaos/validation/structure_factor.hpp"
#include "molchaos/validation/sweep.hpp"

namespace molchaos::validation {
namespace {

constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();

struct RunRecord {
  std::vector<double> tau;                      // per snapshot
  std::vector<std::vector<double>> transverse;  // per snapshot, per shell (|m|² order)
  std::vector<double> temperature;              // per sample
  double breakdown_time = k_nan;
};

struct Box {
  int dimension = 2;
  std::int64_t particles = 0;
  std::vector<double> wavenumbers;
  std::vector<int> wavevectors;
  std::vector<double> sample_times;
  std::vector<RunRecord> runs;
};

Box simulate_box(const BreakdownSpec& spec, std::int64_t particles,
                 const std::function<double(double)>& time_of_tau) {
  Box box;
  box.dimension = spec.dimension;
  box.particles = particles;
  std::vector<double> snapshot_times;
  for (int j = 1; j * spec.snapshot_interval <= spec.collisions_per_particle + 1e-9; ++j)
    snapshot_times.push_back(time_of_tau(j * spec.snapshot_interval));
  for (int r = 0; r < spec.runs; ++r) {
    sim::Parameters p;
    p.dimension = spec.dimension;
    p.particles = particles;
    p.density = spec.density;
    p.restitution = spec.restitution;
    p.seed = derive_seed(spec.base_seed, static_cast<std::uint64_t>(r));
    p.t_end = time_of_tau(spec.collisions_per_particle);
    p.samples_per_decade = 40;
    p.snapshot_times = snapshot_times;
    const sim::RunResult result = sim::run(p);
    RunRecord rec;
    for (const auto& snap : result.snapshots) {
      rec.tau.push_back(
          collisions_per_particle_at(result.samples, snap.t, static_cast<double>(particles)));
      const auto shells = structure_factors(snap, spec.dimension, spec.max_norm2);
      std::vector<double> st;
      for (const auto& s : shells) st.push_back(s.transverse);
      rec.transverse.push_back(st);
      if (box.wavenumbers.empty())
        for (const auto& s : shells) {
          box.wavenumbers.push_back(s.wavenumber);
          box.wavevectors.push_back(s.wavevectors);
        }
    }
    for (const auto& s : result.samples) rec.temperature.push_back(s.temperature);
    if (box.sample_times.empty())
      for (const auto& s : result.samples) box.sample_times.push_back(s.t);
    const Breakdown b = detect_breakdown(result.samples, WindowRule{});
    if (b.detected) rec.breakdown_time = b.time;
    box.runs.push_back(std::move(rec));
  }
  return box;
}

/// value of `estimate` on all runs and its jackknife standard error.
std::pair<double, double> jackknife(
    int runs, const std::function<double(const std::vector<int>&)>& estimate) {
  std::vector<int> all(static_cast<std::size_t>(runs));
  std::iota(all.begin(), all.end(), 0);
  const double full = estimate(all);
  double sum = 0, sum2 = 0;
  int used = 0;
  for (int leave = 0; leave < runs; ++leave) {
    std::vector<int> part;
    for (int r : all)
      if (r != leave) part.push_back(r);
    const double x = estimate(part);
    if (!std::isfinite(x)) continue;
    sum += x;
    sum2 += x * x;
    ++used;
  }
  if (used < 2) return {full, k_nan};
  const double mean = sum / used;
  return {full, std::sqrt((used - 1.0) / used * std::max(0.0, sum2 - used * mean * mean))};
}

double mean_over(const std::vector<int>& runs, const std::function<double(int)>& f) {
  double s = 0;
  for (int r : runs) s += f(r);
  return s / static_cast<double>(runs.size());
}

/// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  if (x.size() < 3) return k_nan;
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  return sxy / sxx;
}

}  // namespace

namespace {

// Slope of ln S⊥ against τ over the snapshots where the prediction lies in [2, fit_max] (past
// the equilibrium start, before the flow energy exceeds ~1 % of the thermal one). A shell whose
// prediction never enters that window (barely unstable) gives no row.
void growth_rows(const Box& box, const theory::TransportCoefficients& c, double fit_max,
                 std::vector<BreakdownRow>& rows) {
  const int runs = static_cast<int>(box.runs.size());
  const std::size_t snaps = box.runs.front().tau.size();
  for (std::size_t shell = 0; shell < std::min<std::size_t>(2, box.wavenumbers.size()); ++shell) {
    const double k = box.wavenumbers[shell];
    if (theory::shear_mode_rate(c, k) <= 0) continue;
    auto fit = [&](const std::vector<int>& sel, bool predicted) {
      std::vector<double> x, y;
      for (std::size_t j = 0; j < snaps; ++j) {
        const double tau = mean_over(sel, [&](int r) { return box.runs[r].tau[j]; });
        const double theory_s = theory::transverse_structure_factor(c, k, tau);
        if (theory_s < 2.0 || theory_s > fit_max) continue;
        const double s =
            predicted ? theory_s
                      : mean_over(sel, [&](int r) { return box.runs[r].transverse[j][shell]; });
        x.push_back(tau);
        y.push_back(std::log(s));
      }
      return slope(x, y);
    };
    std::vector<int> all(static_cast<std::size_t>(runs));
    std::iota(all.begin(), all.end(), 0);
    const double predicted = fit(all, true);
    if (!std::isfinite(predicted)) continue;
    const auto [measured, error] =
        jackknife(runs, [&](const auto& sel) { return fit(sel, false); });
    rows.push_back(
        {fmt::format("d ln S⊥/dτ, |k| = {:.4g} (box {:.0f}σ, |m|² = {})", k,
                     2 * M_PI / box.wavenumbers.front(), shell == 0 ? 1 : 2),
         predicted, measured, error,
         fmt::format("slope over S⊥ ∈ [2, {:g}] of the prediction; asymptotic 2λ = {:.4g}", fit_max,
                     2 * theory::shear_mode_rate(c, k)),
         box.dimension, true});
  }
}

// Below L_c the largest mode relaxes towards S⊥ = νk²/(νk² − ζ/2); compared as the mean over
// the snapshots of the second half of the run, measured and predicted at the same τ.
void stable_row(const Box& box, const theory::TransportCoefficients& c,
                std::vector<BreakdownRow>& rows) {
  const double k = box.wavenumbers.front();
  const double rate = theory::shear_mode_rate(c, k);
  const double ks = k * c.length_unit;
  const double level = -c.shear_viscosity * ks * ks * c.collision_ratio / rate;
  const std::size_t snaps = box.runs.front().tau.size();
  auto estimate = [&](const std::vector<int>& sel, bool predicted) {
    double sum = 0;
    int n = 0;
    for (std::size_t j = snaps / 2; j < snaps; ++j) {
      const double tau = mean_over(sel, [&](int r) { return box.runs[r].tau[j]; });
      sum += predicted ? theory::transverse_structure_factor(c, k, tau)
                       : mean_over(sel, [&](int r) { return box.runs[r].transverse[j][0]; });
      ++n;
    }
    return sum / n;
  };
  const int runs = static_cast<int>(box.runs.size());
  const auto [measured, error] =
      jackknife(runs, [&](const auto& sel) { return estimate(sel, false); });
  std::vector<int> all(static_cast<std::size_t>(runs));
  std::iota(all.begin(), all.end(), 0);
  rows.push_back(
      {fmt::format("S⊥ over the second half of the run, |k| = {:.4g} (box {:.0f}σ < "
                   "L_c)",
                   k, 2 * M_PI / k),
       estimate(all, true), measured, error,
       fmt::format("stationary level {:.4g}, approached at 2λ = {:.4g} per collision per "
                   "particle",
                   level, 2 * rate),
       box.dimension, true});
}

}  // namespace

namespace {

// Linear theory: the flow energy of the growing shear modes over the thermal energy,
// (d−1)/(N d) Σ_k (S⊥(k) − 1) over the full lattice (twice the half space), d = 2. The stable
// shells settle at constant excesses within a few collisions per particle, which the Haff fit's
// T0 absorbs; only the unstable ones make T depart from Haff's law.
double flow_fraction(const Box& box, const theory::TransportCoefficients& c, double tau) {
  double sum = 0;
  for (std::size_t s = 0; s < box.wavenumbers.size(); ++s)
    if (theory::shear_mode_rate(c, box.wavenumbers[s]) > 0)
      sum += box.wavevectors[s] *
             (theory::transverse_structure_factor(c, box.wavenumbers[s], tau) - 1.0);
  return sum / static_cast<double>(box.particles);
}

double first_tau(const std::function<bool(double)>& reached) {
  for (double tau = 0.0; tau < 2000.0; tau += 0.05)
    if (reached(tau)) return tau;
  return k_nan;
}

void onset_rows(const Box& box, const theory::TransportCoefficients& c,
                const std::function<double(double)>& time_of_tau, std::vector<BreakdownRow>& rows) {
  const int runs = static_cast<int>(box.runs.size());
  std::size_t n_samples = box.sample_times.size();
  for (const auto& r : box.runs) n_samples = std::min(n_samples, r.temperature.size());
  const double fit_start = time_of_tau(3.0);
  const double fit_stop =
      time_of_tau(first_tau([&](double t) { return flow_fraction(box, c, t) >= 1e-3; }));
  for (double x : {0.01, 0.02, 0.05}) {
    auto departure = [&](const std::vector<int>& sel) {
      std::vector<sim::Sample> mean(n_samples);
      for (std::size_t i = 0; i < n_samples; ++i) {
        mean[i].t = box.sample_times[i];
        mean[i].temperature = mean_over(sel, [&](int r) { return box.runs[r].temperature[i]; });
      }
      const HaffFit f = fit_haff(mean, fit_start, fit_stop);
      if (!f.ok) return k_nan;
      for (const auto& s : mean)
        if (s.t > fit_start &&
            std::abs(s.temperature / theory::haff_temperature(s.t, f.T0, f.tau0) - 1.0) > x)
          return std::log(s.t);
      return k_nan;
    };
    const auto [measured, error] = jackknife(runs, departure);
    const double tau = first_tau([&](double t) { return flow_fraction(box, c, t) >= x; });
    rows.push_back(
        {fmt::format("ln t: T departs from its Haff fit by {:g} %", 100 * x),
         std::log(time_of_tau(tau)), measured, error,
         fmt::format("prediction: shear-mode flow energy = {:g} % of thermal (τ = {:.3g}); "
                     "fit window t ∈ [{:.3g}, {:.3g}]",
                     100 * x, tau, fit_start, fit_stop)});
  }
  const double threshold = WindowRule{}.velocity_mode_threshold;
  // velocity_mode = ((d−1)S⊥ + S∥)/d at the smallest |k|, with S∥ = 1 (no longitudinal growth).
  const double level = 2.0 * threshold - 1.0;
  const double tau = theory::collisions_to_reach(c, box.wavenumbers.front(), level);
  double sum = 0, sum2 = 0;
  int m = 0;
  for (const auto& r : box.runs)
    if (std::isfinite(r.breakdown_time)) {
      const double l = std::log(r.breakdown_time);
      sum += l;
      sum2 += l * l;
      ++m;
    }
  const double mean = m > 0 ? sum / m : k_nan;
  const double se = m > 1 ? std::sqrt(std::max(0.0, sum2 / m - mean * mean) / (m - 1)) : k_nan;
  rows.push_back({"ln t: break-down detector (velocity mode above its threshold)",
                  std::log(time_of_tau(tau)), mean, se,
                  fmt::format("threshold {:.3g} ⇔ S⊥ = {:.3g} at τ = {:.3g}; detected in {} of {} "
                              "runs",
                              threshold, level, tau, m, runs)});
}

}  // namespace

double collisions_per_particle_at(const std::vector<sim::Sample>& s, double t, double n) {
  auto it = std::lower_bound(s.begin(), s.end(), t,
                             [](const sim::Sample& a, double x) { return a.t < x; });
  if (it == s.begin()) return 2.0 * static_cast<double>(it->collisions) / n;
  if (it == s.end()) return 2.0 * static_cast<double>(s.back().collisions) / n;
  const auto& b = *it;
  const auto& a = *(it - 1);
  const double f = (t - a.t) / (b.t - a.t);
  return 2.0 *
         (static_cast<double>(a.collisions) +
          f * (static_cast<double>(b.collisions) - static_cast<double>(a.collisions))) /
         n;
}

namespace {

// S⊥ of the shells |m|² = 1, 2, 4 (run mean ± standard error) against the prediction.
void append_curves(const Box& box, const theory::TransportCoefficients& c,
                   std::vector<StructureFactorCurve>& curves) {
  const auto runs = static_cast<double>(box.runs.size());
  for (std::size_t shell = 0; shell < std::min<std::size_t>(3, box.wavenumbers.size()); ++shell) {
    StructureFactorCurve curve;
    curve.dimension = box.dimension;
    curve.wavenumber = box.wavenumbers[shell];
    curve.box = 2 * M_PI / box.wavenumbers.front();
    for (std::size_t j = 0; j < box.runs.front().tau.size(); ++j) {
      double tau = 0, sum = 0, sum2 = 0;
      for (const auto& r : box.runs) {
        tau += r.tau[j] / runs;
        sum += r.transverse[j][shell];
        sum2 += r.transverse[j][shell] * r.transverse[j][shell];
      }
      const double mean = sum / runs;
      curve.tau.push_back(tau);
      curve.measured.push_back(mean);
      curve.error.push_back(std::sqrt(std::max(0.0, sum2 / runs - mean * mean) / (runs - 1)));
      curve.predicted.push_back(theory::transverse_structure_factor(c, curve.wavenumber, tau));
    }
    curves.push_back(std::move(curve));
  }
}

}  // namespace

// The d = 3 set, chosen from the theory alone (`molchaos theory --dim 3 --restitution 0.7
// --density 0.2 --particles 2800`): at the paper's n = 0.05, ε = 0.93, L_c = 131σ and a box
// above it needs ~10^5 spheres. At ε = 0.7, n = 0.2 (packing fraction 0.105, where the Enskog
// coefficients in the first Sonine approximation hold) L_c = 2π/k⊥ = 16.6σ and the heat mode's
// 2π/k∥ = 26.9σ. N = 2800 gives a box of 24.1σ between the two, so only the shear mode of the
// smallest |k| grows (2λ = 0.0894 per collision per particle); N = 550 gives 14.0σ < L_c, whose
// largest mode relaxes to S⊥ = 1/(1 − (L/L_c)²) ≈ 3.5. S⊥ = 10 of the three wavevectors of
// |m|² = 1 holds, with both transverse components, a flow energy of 4·9/2800 ≈ 1.3 % of the
// thermal one, as S⊥ = 30 of |m|² = 1 does at N = 5000 in d = 2: the fit window ends there.
BreakdownSpec BreakdownSpec::three_dimensional() {
  BreakdownSpec s;
  s.dimension = 3;
  s.density = 0.2;
  s.restitution = 0.7;
  s.unstable_particles = 2800;
  s.stable_particles = 550;
  s.runs = 32;
  s.collisions_per_particle = 30.0;
  s.snapshot_interval = 1.0;
  s.fit_max_transverse = 10.0;
  s.max_norm2 = 4;       // |m|² = 1, 2 (unstable at 24.1σ) and 3, 4 for the curves
  s.onset_rows = false;  // the runs end at τ = 30, sized for the linear regime only
  s.base_seed = 9003;
  return s;
}

std::vector<BreakdownRow> breakdown_study(const BreakdownSpec& spec,
                                          std::vector<StructureFactorCurve>* curves) {
  const auto c = theory::transport_coefficients(
      {spec.dimension, spec.density, spec.restitution, std::nullopt});
  theory::CoolingInputs in;
  in.dimension = spec.dimension;
  in.density = spec.density;
  in.restitution = spec.restitution;
  const auto cooling = theory::predict_cooling(in);
  const double tau0 = cooling.tau0.value, omega = cooling.enskog_collision_frequency;
  // Haff's law: τ(t) = ω_E(T0) τ0 ln(1 + t/τ0), inverted.
  const std::function<double(double)> time_of_tau = [=](double tau) {
    return tau0 * std::expm1(tau / (omega * tau0));
  };
  std::vector<BreakdownRow> rows;
  const Box unstable = simulate_box(spec, spec.unstable_particles, time_of_tau);
  const Box stable = simulate_box(spec, spec.stable_particles, time_of_tau);
  rows.push_back({"critical box L_c = 2π/k⊥ [σ]", theory::critical_box_size(c), k_nan, k_nan,
                  fmt::format("boxes simulated: {:.0f}σ (largest mode unstable), {:.0f}σ (stable)",
                              2 * M_PI / unstable.wavenumbers.front(),
                              2 * M_PI / stable.wavenumbers.front())});
  growth_rows(unstable, c, spec.fit_max_transverse, rows);
  stable_row(stable, c, rows);
  if (spec.onset_rows) onset_rows(unstable, c, time_of_tau, rows);
  for (auto& r : rows) r.dimension = spec.dimension;
  if (curves) {
    append_curves(unstable, c, *curves);
    append_curves(stable, c, *curves);
  }
  return rows;
}

std::string breakdown_markdown(const std::vector<BreakdownRow>& rows) {
  std::string s = "| quantity | predicted | measured | note |\n|---|---|---|---|\n";
  for (const auto& r : rows)
    s += fmt::format("| {} | {:.4g} | {} | {} |\n", r.quantity, r.predicted,
                     std::isfinite(r.measured)
                         ? fmt::format("{:.4g} ± {:.2g}", r.measured, r.measured_error)
                         : std::string("–"),
                     r.note);
  return s;
}

}  // namespace molchaos::validation
