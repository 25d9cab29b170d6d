// The original and the randomized gases through the break-down (see the header). Every gas runs
// from the same initial states (same seeds), so differences between the gases are the shuffle's.
#include "molchaos/validation/gas_fields.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "molchaos/sim/run.hpp"
#include "molchaos/theory/hydrodynamics.hpp"
#include "molchaos/validation/breakdown.hpp"
#include "molchaos/validation/structure_factor.hpp"
#include "molchaos/validation/sweep.hpp"

namespace molchaos::validation {
namespace {

// Linear hydrodynamics of the original gas (theory/hydrodynamics): S⊥ of the shells |m|² ≤
// max_norm2 averaged over their wavevectors, at τ collisions per particle. A shuffled gas has no
// velocity correlations: S⊥ = 1.
double predicted_transverse(const GasFieldSpec& spec, const std::string& mode, double box,
                            double tau) {
  if (mode != "none") return 1.0;
  const auto c = theory::transport_coefficients({2, spec.density, spec.restitution, std::nullopt});
  double sum = 0, vectors = 0;
  // the half space of the lattice, as structure_factors() counts it
  const int r = static_cast<int>(std::sqrt(static_cast<double>(spec.max_norm2)));
  const double unit = 2 * M_PI / box;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y) {
      const int n2 = x * x + y * y;
      const bool upper = x > 0 || (x == 0 && y > 0);
      if (n2 == 0 || n2 > spec.max_norm2 || !upper) continue;
      sum += theory::transverse_structure_factor(c, unit * std::sqrt(static_cast<double>(n2)), tau);
      vectors += 1;
    }
  return sum / vectors;
}

struct SnapshotValues {
  double tau = 0, transverse = 0, density = 0, flow_fraction = 0, density_contrast = 0;
};

SnapshotValues measure(const sim::Snapshot& snap, const std::vector<sim::Sample>& samples,
                       const GasFieldSpec& spec, std::vector<double>& wavenumbers) {
  SnapshotValues v;
  v.tau = collisions_per_particle_at(samples, snap.t, static_cast<double>(spec.particles));
  const auto shells = structure_factors(snap, 2, spec.max_norm2);
  double vectors = 0;
  for (const auto& s : shells) {
    v.transverse += s.wavevectors * s.transverse;
    v.density += s.wavevectors * s.density;
    vectors += s.wavevectors;
  }
  v.transverse /= vectors;
  v.density /= vectors;
  if (wavenumbers.empty())
    for (const auto& s : shells) wavenumbers.push_back(s.wavenumber);
  const CoarseField f = coarse_grain(snap, 2, spec.cells);
  const double n = static_cast<double>(spec.particles);
  // A gas without velocity correlations has T_flow = T·(occupied cells)/N from sampling alone.
  v.flow_fraction = (f.flow_temperature - f.temperature * f.occupied_cells / n) / f.temperature;
  const double mean = n / static_cast<double>(f.number.size());
  double var = 0;
  for (double c : f.number) var += (c - mean) * (c - mean);
  v.density_contrast = var / static_cast<double>(f.number.size()) / mean;
  return v;
}

Measurement mean_and_error(const std::vector<double>& x) {
  const double n = static_cast<double>(x.size());
  double sum = 0, sum2 = 0;
  for (double v : x) {
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n;
  return {mean, n > 1 ? std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1)) : 0.0};
}

std::string gas_title(const std::string& mode) {
  if (mode == "none") return "original gas";
  if (mode == "paper") return "paper's shuffle";
  return "flux shuffle";
}

}  // namespace

std::vector<double> animation_log_times(const GasFieldSpec& spec) {
  std::vector<double> out;
  if (spec.animation_frames < 1 || spec.field_log_times.empty()) return out;
  const double first = spec.animation_first_log_time, last = spec.field_log_times.back();
  if (spec.animation_frames == 1) return {last};
  for (int i = 0; i < spec.animation_frames; ++i)
    out.push_back(first + (last - first) * i / (spec.animation_frames - 1));
  return out;
}

namespace {

// Appends to `rows[i]` the long-wave panel of the snapshot taken at ln t = log_times[i], if any.
void add_panels(const sim::Snapshot& snap, const GasFieldSpec& spec, const std::string& mode,
                const std::vector<double>& log_times, FlowFieldData& data) {
  for (std::size_t i = 0; i < log_times.size(); ++i)
    if (std::abs(snap.t - std::exp(log_times[i])) <= 1e-9 * snap.t)
      data.rows[i].push_back(
          long_wave_panel(snap, spec.field_cells, spec.field_max_norm2,
                          fmt::format("{}, ln t = {:.3g}", gas_title(mode), log_times[i])));
}

}  // namespace

GasFieldStudy gas_field_study(const GasFieldSpec& spec) {
  if (spec.runs < 2) throw std::invalid_argument("runs: need at least 2 for an error bar");
  GasFieldStudy study;
  study.spec = spec;
  study.fields.rows.resize(spec.field_log_times.size());
  const std::vector<double> frames = animation_log_times(spec);
  study.animation.rows.resize(frames.size());
  for (const auto& mode_name : spec.modes) {
    const auto mode = sim::parse_randomization(mode_name);
    if (!mode) throw std::invalid_argument("modes: unknown randomization " + mode_name);
    // values[time][run]
    std::vector<std::vector<SnapshotValues>> values(spec.log_times.size());
    GasFieldSeries series;
    series.mode = mode_name;
    const bool animated = std::find(spec.animation_modes.begin(), spec.animation_modes.end(),
                                    mode_name) != spec.animation_modes.end();
    for (int r = 0; r < spec.runs; ++r) {
      sim::Parameters p;
      p.dimension = 2;
      p.particles = spec.particles;
      p.density = spec.density;
      p.restitution = spec.restitution;
      p.randomize = *mode;
      p.seed = derive_seed(spec.base_seed, static_cast<std::uint64_t>(r));
      p.samples_per_decade = 40;
      for (double l : spec.log_times) p.snapshot_times.push_back(std::exp(l));
      if (r == 0)
        for (double l : spec.field_log_times) p.snapshot_times.push_back(std::exp(l));
      // Snapshots only read the state: the run's trajectory stays the same bytes with them.
      if (r == 0 && animated)
        for (double l : frames) p.snapshot_times.push_back(std::exp(l));
      std::sort(p.snapshot_times.begin(), p.snapshot_times.end());
      p.snapshot_times.erase(std::unique(p.snapshot_times.begin(), p.snapshot_times.end()),
                             p.snapshot_times.end());
      p.t_end = p.snapshot_times.back();
      const sim::RunResult result = sim::run(p);
      study.box = result.snapshots.front().box;
      for (const auto& snap : result.snapshots) {
        for (std::size_t i = 0; i < spec.log_times.size(); ++i)
          if (std::abs(snap.t - std::exp(spec.log_times[i])) <= 1e-9 * snap.t)
            values[i].push_back(measure(snap, result.samples, spec, study.wavenumbers));
        if (r != 0) continue;
        add_panels(snap, spec, mode_name, spec.field_log_times, study.fields);
        if (animated) add_panels(snap, spec, mode_name, frames, study.animation);
      }
    }
    study.fields.column_titles.push_back(gas_title(mode_name));
    if (animated) study.animation.column_titles.push_back(gas_title(mode_name));
    for (std::size_t i = 0; i < spec.log_times.size(); ++i) {
      if (values[i].size() != static_cast<std::size_t>(spec.runs))
        throw std::runtime_error("gas_field_study: a run ended before its snapshot times");
      GasFieldPoint pt;
      pt.log_time = spec.log_times[i];
      std::vector<double> tau, st, sd, ff, dc;
      for (const auto& v : values[i]) {
        tau.push_back(v.tau);
        st.push_back(v.transverse);
        sd.push_back(v.density);
        ff.push_back(v.flow_fraction);
        dc.push_back(v.density_contrast);
      }
      pt.tau = mean_and_error(tau).value;
      pt.transverse_predicted = predicted_transverse(spec, mode_name, study.box, pt.tau);
      pt.transverse = mean_and_error(st);
      pt.density = mean_and_error(sd);
      pt.flow_fraction = mean_and_error(ff);
      pt.density_contrast = mean_and_error(dc);
      series.points.push_back(pt);
      series.run_transverse.push_back(st);
      series.run_density.push_back(sd);
    }
    study.series.push_back(std::move(series));
  }
  return study;
}

namespace {

std::vector<double> window_means(const GasFieldStudy& s,
                                 const std::vector<std::vector<double>>& values, double lo,
                                 double hi) {
  std::vector<double> out(static_cast<std::size_t>(s.spec.runs), 0.0);
  int used = 0;
  for (std::size_t i = 0; i < s.spec.log_times.size() && i < values.size(); ++i) {
    if (s.spec.log_times[i] < lo || s.spec.log_times[i] > hi) continue;
    ++used;
    for (std::size_t r = 0; r < out.size(); ++r) out[r] += values[i][r];
  }
  if (used == 0) throw std::invalid_argument("window: no snapshot time in [lo, hi]");
  for (auto& x : out) x /= used;
  return out;
}

}  // namespace

Measurement window_transverse(const GasFieldStudy& s, const GasFieldSeries& g, double lo,
                              double hi) {
  return mean_and_error(window_means(s, g.run_transverse, lo, hi));
}

Measurement window_density(const GasFieldStudy& s, const GasFieldSeries& g, double lo, double hi) {
  return mean_and_error(window_means(s, g.run_density, lo, hi));
}

Measurement density_growth(const GasFieldStudy& s, const GasFieldSeries& g, double early_end,
                           double late_start) {
  const auto early = window_means(s, g.run_density, -1e300, early_end);
  auto late = window_means(s, g.run_density, late_start, 1e300);
  for (std::size_t r = 0; r < late.size(); ++r) late[r] -= early[r];
  return mean_and_error(late);
}

std::string gas_field_csv(const GasFieldStudy& s) {
  std::string out = fmt::format(
      "# the original and the randomized gases through the break-down of the HCS, d = 2\n"
      "# particles = {}\n# density = {}\n# restitution = {}\n# runs = {}\n# box = {:.6g}\n"
      "# cells = {}\n# shells = |m|^2 <= {} (k = {:.6g})\n# runs seeded from base seed {}\n"
      "# S_perp, S: mean over the shells' wavevectors; flow_fraction = (T_flow - noise)/T; "
      "density_contrast = var(N_cell)/mean(N_cell); errors: standard error over the runs\n",
      s.spec.particles, s.spec.density, s.spec.restitution, s.spec.runs, s.box, s.spec.cells,
      s.spec.max_norm2, fmt::join(s.wavenumbers, ", "), s.spec.base_seed);
  out +=
      "mode,ln_t,tau,S_perp,S_perp_error,S_perp_predicted,S,S_error,flow_fraction,flow_fraction_"
      "error,"
      "density_contrast,density_contrast_error\n";
  for (const auto& g : s.series)
    for (const auto& p : g.points)
      out += fmt::format(
          "{},{:g},{:.6g},{:.6g},{:.3g},{:.6g},{:.6g},{:.3g},{:.6g},{:.3g},{:.6g},"
          "{:.3g}\n",
          g.mode, p.log_time, p.tau, p.transverse.value, p.transverse.error, p.transverse_predicted,
          p.density.value, p.density.error, p.flow_fraction.value, p.flow_fraction.error,
          p.density_contrast.value, p.density_contrast.error);
  return out;
}

}  // namespace molchaos::validation
