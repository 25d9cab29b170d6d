// run(Parameters): initial state, elastic relaxation, the cooling run on the sample grid.
#include "molchaos/sim/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <type_traits>

#include "molchaos/sim/dsmc.hpp"
#include "molchaos/sim/engine.hpp"
#include "molchaos/version.hpp"

namespace molchaos::sim {
namespace {

constexpr std::uint64_t k_progress_events = 1u << 20;

// Observer: ContactStatistics when the run records them, else NoObserver (nothing per collision).
template <int D, class Observer>
RunResult run_d(const Parameters& p, const ProgressReporter& progress) {
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  using RunEngine = Engine<D, Observer>;
  RunEngine engine(p);
  engine.relax(p.relax_collisions_per_particle);

  RunResult result;
  result.parameters = p;
  result.version = k_version;
  result.stop_reason = StopReason::t_end;

  const std::vector<double> samples = sample_times(p);
  std::vector<double> snapshots = p.snapshot_times;
  std::sort(snapshots.begin(), snapshots.end());
  std::vector<double> targets = samples;
  targets.insert(targets.end(), snapshots.begin(), snapshots.end());
  std::sort(targets.begin(), targets.end());
  targets.erase(std::unique(targets.begin(), targets.end()), targets.end());

  std::size_t next_sample = 0, next_snapshot = 0;
  for (double t : targets) {
    auto status = engine.advance_to(t, k_progress_events);
    while (status == RunEngine::Status::paused) {
      if (progress)
        progress({engine.time() / p.t_end, engine.collisions(), engine.events(), elapsed()});
      status = engine.advance_to(t, k_progress_events);
    }
    auto take_sample = [&engine] {
      Sample s = engine.sample();
      if constexpr (std::is_same_v<Observer, ContactStatistics>)
        s.contacts = engine.observer().take();
      return s;
    };
    if (status == RunEngine::Status::stopped) {
      result.stop_reason = engine.stop_reason();
      result.samples.push_back(take_sample());  // the state where the run stopped
      break;
    }
    if (next_sample < samples.size() && samples[next_sample] == t) {
      Sample s = take_sample();
      s.t = t;
      result.samples.push_back(s);
      ++next_sample;
    }
    while (next_snapshot < snapshots.size() && snapshots[next_snapshot] == t) {
      Snapshot snap = engine.snapshot();
      snap.t = t;
      result.snapshots.push_back(std::move(snap));
      ++next_snapshot;
    }
  }
  result.collisions = engine.collisions();
  result.events = engine.events();
  result.wall_seconds = elapsed();
  if (progress) progress({1.0, result.collisions, result.events, result.wall_seconds});
  return result;
}

}  // namespace

std::vector<double> sample_times(const Parameters& p) {
  std::vector<double> times{0.0};
  for (int j = 0;; ++j) {
    const double t =
        p.t_first_sample * std::pow(10.0, static_cast<double>(j) / p.samples_per_decade);
    if (t >= p.t_end * (1 - 1e-12)) break;
    times.push_back(t);
  }
  times.push_back(p.t_end);
  return times;
}

double contact_value_g2(int dimension, double density) {
  if (dimension == 2) {
    const double eta = std::numbers::pi * density / 4.0;  // Henderson
    return (1.0 - 7.0 * eta / 16.0) / ((1.0 - eta) * (1.0 - eta));
  }
  const double eta = std::numbers::pi * density / 6.0;  // Carnahan-Starling
  return (1.0 - eta / 2.0) / std::pow(1.0 - eta, 3);
}

double enskog_collision_frequency(int dimension, double density, double temperature) {
  const double prefactor = dimension == 2 ? 2.0 : 4.0;
  return prefactor * density * contact_value_g2(dimension, density) *
         std::sqrt(std::numbers::pi * temperature);
}

RunResult run_with_progress(const Parameters& p, const ProgressReporter& progress) {
  validate(p);
  if (p.method == Method::dsmc) {  // the one place the method is chosen
    ProgressCallback fraction;
    if (progress) fraction = [&](double f) { progress({f, 0, 0, 0.0}); };
    return run_dsmc(p, fraction);
  }
  if (p.contact_statistics)
    return p.dimension == 2 ? run_d<2, ContactStatistics>(p, progress)
                            : run_d<3, ContactStatistics>(p, progress);
  return p.dimension == 2 ? run_d<2, NoObserver>(p, progress) : run_d<3, NoObserver>(p, progress);
}

RunResult run(const Parameters& p, const ProgressCallback& progress) {
  ProgressReporter reporter;
  if (progress) reporter = [&](const Progress& report) { progress(report.fraction_done); };
  return run_with_progress(p, reporter);
}

}  // namespace molchaos::sim
