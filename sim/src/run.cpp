// run(Parameters): initial state, elastic relaxation, the cooling run on the sample grid; its
// checkpoints and restarts (checkpoint.hpp).
#include "molchaos/sim/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "molchaos/sim/checkpoint.hpp"
#include "molchaos/sim/dsmc.hpp"
#include "molchaos/sim/engine.hpp"
#include "molchaos/sim/initial_state.hpp"
#include "molchaos/sim/memory_need.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/sim/relaxed_states.hpp"
#include "molchaos/version.hpp"

namespace molchaos::sim {
namespace {

constexpr std::uint64_t k_progress_events = 1u << 20;

// The run's state beside the engine's in a checkpoint: the last target reached (whose samples and
// snapshots are taken), the wall time spent, the samples and snapshots so far.
void save_run(CheckpointWriter& out, double done, double wall_seconds, const RunResult& result) {
  out(done, wall_seconds, result.samples, static_cast<std::uint64_t>(result.snapshots.size()));
  for (const Snapshot& snap : result.snapshots)
    out(snap.t, snap.box, snap.collisions, snap.positions, snap.velocities);
}

// The samples and snapshots so far are checked as the engine's state is (check_restored()): a
// file edited with its checksum recomputed would otherwise put its numbers into the results.
void restore_run(CheckpointReader& in, const Parameters& p, double& done, double& wall_seconds,
                 RunResult& result) {
  std::uint64_t snapshots = 0;
  in(done, wall_seconds, result.samples, snapshots);
  if (!(std::isfinite(done) && std::isfinite(wall_seconds) && wall_seconds >= 0))
    in.fail("time reached or wall time spent (" + std::to_string(done) + ", " +
            std::to_string(wall_seconds) + " s) not a finite time >= 0");
  const Sample* previous = nullptr;
  for (const Sample& s : result.samples) {
    const bool numbers = std::isfinite(s.t) && s.t <= done && std::isfinite(s.temperature) &&
                         s.temperature >= 0 && std::isfinite(s.a2) &&
                         std::isfinite(s.velocity_mode) && s.velocity_mode >= 0 &&
                         std::isfinite(s.density_mode) && s.density_mode >= 0 &&
                         s.collisions <= s.events && s.contacts.well_formed();
    const bool in_order =
        previous == nullptr ||
        (previous->t < s.t && previous->collisions <= s.collisions && previous->events <= s.events);
    if (!numbers || !in_order)
      in.fail("sample at t = " + message_number(s.t) +
              " not finite, not in time order, or after the time the run had reached");
    previous = &s;
  }
  if (snapshots > 1u << 20) in.fail("corrupt snapshot count");
  result.snapshots.resize(static_cast<std::size_t>(snapshots));
  const std::size_t values = static_cast<std::size_t>(p.dimension * p.particles);
  for (Snapshot& snap : result.snapshots) {
    in(snap.t, snap.box, snap.collisions, snap.positions, snap.velocities);
    const auto finite = [](const std::vector<double>& x) {
      return std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
    };
    if (!(std::isfinite(snap.t) && snap.t <= done && std::isfinite(snap.box) && snap.box > 0 &&
          snap.positions.size() == values && snap.velocities.size() == values &&
          finite(snap.positions) && finite(snap.velocities)))
      in.fail("snapshot at t = " + message_number(snap.t) +
              " not of N particles with finite values, or after the time the run had reached");
  }
}

template <class RunEngine>
std::string run_layout() {
  return RunEngine::checkpoint_layout() + " sample " + std::to_string(sizeof(Sample)) +
         " snapshot " + std::to_string(sizeof(Snapshot));
}

// The relaxation, or its end state restored from an earlier run of the same key
// (relaxed_states.hpp): the same state either way, bit for bit.
// A run without relaxation keeps nothing: its state is the constructor's, which costs no more
// to rebuild than to restore.
template <class RunEngine>
bool relax_or_restore(RunEngine& engine, const Parameters& p, const std::function<bool()>& go_on) {
  const bool shared = relaxed_states_shared() && p.relax_collisions_per_particle > 0 &&
                      engine.memory_bytes() <= k_largest_kept_state;
  const std::string key = shared ? relaxed_state_key(p, run_layout<RunEngine>()) : std::string();
  if (shared)
    if (const auto state = find_relaxed_state(key)) {
      CheckpointReader in(*state, "relaxed state " + key);
      engine.restore_state(in);
      in.finish();
      return true;
    }
  if (!engine.relax(p.relax_collisions_per_particle, go_on)) return false;
  if (!shared) return true;
  CheckpointWriter out;
  engine.save_state(out);
  keep_relaxed_state(key, out.data());
  return true;
}

// Observer: ContactStatistics when the run records them, else NoObserver (nothing per collision).
// Checkpoints are written and interrupts obeyed only between advance_to() calls (at sample
// times and at the progress pauses, each reported to `progress`), where stopping changes nothing in
// the engine's state; with none asked for, the run does exactly what it did without them.
template <int D, class Observer>
std::optional<RunResult> run_d(const Parameters& p, const ProgressReporter& progress,
                               const CheckpointOptions& checkpoints) {
  const auto start = std::chrono::steady_clock::now();
  double wall_before = 0;  // seconds spent before a restart
  auto elapsed = [&] {
    return wall_before +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  using RunEngine = Engine<D, Observer>;
  RunEngine engine(p, checkpoints.interrupt);  // InitialStateInterrupted: caught by the caller
  engine.check_run_length(p.t_end);  // before the relaxation, which it would waste

  RunResult result;
  result.parameters = p;
  result.version = k_version;
  result.stop_reason = StopReason::t_end;
  double done = -std::numeric_limits<double>::infinity();  // last target reached and observed
  auto interrupted = [&] {
    return checkpoints.interrupt != nullptr && checkpoints.interrupt->load();
  };
  if (checkpoints.restart.empty()) {
    // Relaxing: pauses for the progress reporter and an interrupt, which returns no result
    // (a half-relaxed state has nothing to checkpoint).
    const auto go_on = [&] {
      if (progress) progress({0.0, engine.collisions(), engine.events(), elapsed(), true});
      return !interrupted();
    };
    if (!relax_or_restore(engine, p, go_on)) return std::nullopt;
  } else {
    double saved_t_end = 0;
    CheckpointReader in =
        read_checkpoint_file(checkpoints.restart, p, run_layout<RunEngine>(), &saved_t_end);
    restore_run(in, p, done, wall_before, result);
    engine.restore_state(in);
    in.finish();
    engine.check_restored(in);  // a file from outside (a relaxed state here is this process's)
    if (engine.time() < done - 1e-9 * std::max(1.0, std::abs(done)))
      in.fail("engine's time " + message_number(engine.time()) +
              " lies before the time the run had reached, " + message_number(done));
    // A new t_end keeps the sample grid below both ends: the samples taken stay valid.
    // A t_end equal to the checkpoint's time (or to the last sample time it reached, within the
    // grid's rounding) leaves nothing to run: refused as well, saying so.
    if (p.t_end != saved_t_end && !(engine.time() < p.t_end && done < p.t_end * (1 - 1e-12))) {
      const std::string time = message_number(engine.time());
      const bool equal = p.t_end >= engine.time();
      throw CheckpointError(
          "checkpoint " + checkpoints.restart + ": t_end = " + message_number(p.t_end) +
          (equal ? " equals the checkpoint's time " + time + ", which leaves nothing to run"
                 : " lies before the checkpoint's time " + time) +
          "; allowed: t_end in (" + time + ", inf), or the checkpoint's own " +
          message_number(saved_t_end));
    }
  }
  if (checkpoints.under_way != nullptr) checkpoints.under_way->store(true);

  const std::vector<double> samples = sample_times(p);
  std::vector<double> snapshots = p.snapshot_times;
  std::sort(snapshots.begin(), snapshots.end());
  std::vector<double> targets = samples;
  targets.insert(targets.end(), snapshots.begin(), snapshots.end());
  std::sort(targets.begin(), targets.end());
  targets.erase(std::unique(targets.begin(), targets.end()), targets.end());

  const double t_start = std::max(done, 0.0);
  double last_wall = elapsed(), next_checkpoint = t_start + checkpoints.interval;
  CheckpointRecord record;
  record.start = t_start;
  auto save = [&] {
    if (checkpoints.path.empty()) return;
    CheckpointWriter out;
    save_run(out, done, elapsed(), result);
    engine.save_state(out);
    write_checkpoint_file(checkpoints.path, p, run_layout<RunEngine>(), out.data());
    last_wall = elapsed();
  };
  // A periodic checkpoint is a safety net: one that cannot be written (a full disk) leaves the
  // run and its result as they are, and the file as the last write left it (whole: the write is
  // atomic, its temporary removed). With write_failed the run goes on, warned; without, it ends.
  auto save_periodic = [&] {
    ++record.due;
    try {
      save();
    } catch (const std::exception& e) {
      if (!checkpoints.write_failed) throw;
      checkpoints.write_failed(engine.time(), e.what());
      last_wall = elapsed();  // the next try a whole wall interval later, not at every pause
    }
  };
  auto wall_due = [&] {
    return checkpoints.wall_interval > 0 && elapsed() - last_wall >= checkpoints.wall_interval;
  };

  std::size_t next_sample = static_cast<std::size_t>(
      std::upper_bound(samples.begin(), samples.end(), done) - samples.begin());
  std::size_t next_snapshot = static_cast<std::size_t>(
      std::upper_bound(snapshots.begin(), snapshots.end(), done) - snapshots.begin());
  for (double t : targets) {
    if (t <= done) continue;  // reached before the restart
    auto status = engine.advance_to(t, k_progress_events);
    while (status == RunEngine::Status::paused) {
      if (progress)
        progress({engine.time() / p.t_end, engine.collisions(), engine.events(), elapsed()});
      if (interrupted()) {
        save();
        return std::nullopt;
      }
      if (wall_due()) save_periodic();
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
    done = t;
    if (t == targets.back()) break;  // finished: nothing left to checkpoint
    // At every sample time too, not only at the pauses: a cooling run's sample intervals can all
    // fall short of a pause, and a front end that looks for signals here (Python's handlers run
    // only when it asks) would see none until the end.
    if (progress) progress({t / p.t_end, engine.collisions(), engine.events(), elapsed()});
    if (interrupted()) {
      save();
      return std::nullopt;
    }
    record.longest_interval = t - t_start;
    if ((checkpoints.interval > 0 && t >= next_checkpoint) || wall_due()) {
      save_periodic();
      next_checkpoint = t + checkpoints.interval;
    }
  }
  if (checkpoints.record != nullptr) *checkpoints.record = record;
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

std::optional<RunResult> run_with_checkpoints(const Parameters& p, const ProgressReporter& progress,
                                              const CheckpointOptions& checkpoints) {
  validate(p);
  require_memory(p, memory_limit_bytes());
  if (p.method == Method::dsmc) {  // the one place the method is chosen
    // DSMC runs take seconds where MD runs take hours; its state has no checkpoint format.
    if (!checkpoints.path.empty() || !checkpoints.restart.empty())
      throw std::invalid_argument(
          "checkpoint: checkpoints and restarts are made by the event-driven method only "
          "(method = edmd), not by method = dsmc");
    ProgressCallback fraction;
    if (progress) fraction = [&](double f) { progress({f, 0, 0, 0.0}); };
    return run_dsmc(p, fraction);
  }
  try {
    if (p.contact_statistics)
      return p.dimension == 2 ? run_d<2, ContactStatistics>(p, progress, checkpoints)
                              : run_d<3, ContactStatistics>(p, progress, checkpoints);
    return p.dimension == 2 ? run_d<2, NoObserver>(p, progress, checkpoints)
                            : run_d<3, NoObserver>(p, progress, checkpoints);
  } catch (const InitialStateInterrupted&) {  // before the relaxation: nothing to save
    return std::nullopt;
  }
}

RunResult run_with_progress(const Parameters& p, const ProgressReporter& progress) {
  return *run_with_checkpoints(p, progress, CheckpointOptions{});  // never interrupted
}

RunResult run(const Parameters& p, const ProgressCallback& progress) {
  ProgressReporter reporter;
  if (progress) reporter = [&](const Progress& report) { progress(report.fraction_done); };
  return run_with_progress(p, reporter);
}

}  // namespace molchaos::sim
