// Speed of the event-driven engine (Google Benchmark; `make bench`). Counters: collisions/s and
// events/s over a fixed number of collisions after a short elastic relaxation (not timed), bytes
// per particle held by the engine, and the process's peak resident memory (VmHWM) per particle.
// Cases: d = 2 at n = 0.05, 0.1 for N = 1e3 ... 1e6 (restitution 0.9, the paper's kind of run);
// d = 3 elastic at packing fractions 0.1 and 0.4 with N = 1e5 (the work Smallenburg's codes are
// timed on); early and late in a long cooling run (velocity rescaling keeps the speed).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <tuple>

#include "engine_cases.hpp"
#include "molchaos/sim/engine.hpp"
#include "molchaos/sim/run.hpp"

namespace {

using molchaos::sim::Engine;
using molchaos::sim::Parameters;
using molchaos::sim::Randomization;

// CPU time of this thread: the machine may be shared, so rates are given per wall second and per
// CPU second.
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Peak resident set size of the process in bytes (VmHWM from /proc/self/status), 0 if unknown.
double peak_resident_bytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kilobytes = 0;
      status >> kilobytes;
      return kilobytes * 1024.0;
    }
    std::getline(status, key);
  }
  return 0;
}

template <int D>
void time_collisions(benchmark::State& state, const Parameters& p, std::uint64_t collisions) {
  Engine<D> engine(p);
  engine.relax(p.relax_collisions_per_particle);
  double seconds = 0, cpu_seconds = 0;
  std::uint64_t done = 0, events = 0;
  for (auto _ : state) {
    engine.resume();
    const std::uint64_t c0 = engine.collisions(), e0 = engine.events();
    engine.set_collision_limit(c0 + collisions);
    const double cpu0 = thread_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    engine.advance_to(1e300);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cpu_seconds += thread_cpu_seconds() - cpu0;
    seconds += wall;
    done += engine.collisions() - c0;
    events += engine.events() - e0;
    state.SetIterationTime(wall);
  }
  const double n = static_cast<double>(p.particles);
  state.counters["collisions_per_s"] = static_cast<double>(done) / seconds;
  state.counters["collisions_per_cpu_s"] = static_cast<double>(done) / cpu_seconds;
  state.counters["events_per_s"] = static_cast<double>(events) / seconds;
  state.counters["events_per_cpu_s"] = static_cast<double>(events) / cpu_seconds;
  state.counters["events_per_collision"] = static_cast<double>(events) / static_cast<double>(done);
  state.counters["engine_bytes_per_particle"] = static_cast<double>(engine.memory_bytes()) / n;
  state.counters["peak_rss_bytes_per_particle"] = peak_resident_bytes() / n;
  state.counters["final_T"] = engine.temperature();
  state.SetLabel(engine.uses_neighbour_lists() ? "neighbour lists" : "cell crossings");
}

// d = 2, N = range(0), density = range(1) / 100, restitution 0.9, no shuffle.
void bm_disks(benchmark::State& state) {
  const Parameters p = molchaos::bench::disks_case(state.range(0),
                                                    static_cast<double>(state.range(1)) / 100.0);
  // 20 collisions per particle (bounded to [2e5, 2e6]): long enough to time, short of clustering.
  const auto collisions =
      static_cast<std::uint64_t>(std::clamp(20.0 * static_cast<double>(p.particles), 2e5, 2e6));
  time_collisions<2>(state, p, collisions);
}
BENCHMARK(bm_disks)
    ->ArgsProduct({{1000, 10000, 100000, 1000000}, {5, 10}})
    ->ArgNames({"N", "n_percent"})
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// The paper's run (Fig. 3): d = 2, N = 5000, n = 0.05, restitution 0.93, shuffle range(0)
// (0 none, 1 paper, 2 flux); 2e5 collisions (40 per particle, well before clustering).
void bm_paper_case(benchmark::State& state) {
  time_collisions<2>(state, molchaos::bench::paper_case(static_cast<Randomization>(state.range(0))),
                     200000);
}
BENCHMARK(bm_paper_case)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->ArgNames({"shuffle"})
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// d = 3 elastic spheres, N = 1e5, packing fraction range(0) / 100.
void bm_spheres(benchmark::State& state) {
  time_collisions<3>(state,
                     molchaos::bench::spheres_case(static_cast<double>(state.range(0)) / 100.0),
                     2000000);
}
BENCHMARK(bm_spheres)
    ->Arg(10)
    ->Arg(40)
    ->ArgNames({"packing_percent"})
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// Early and late in one long cooling run (d = 2, N = 5000, n = 0.05, restitution 0.9, flux
// shuffle so that the gas stays homogeneous): collisions/s over the first 1e5 collisions (T from
// 1 to ~1e-3) and over 1e5 collisions after T has fallen below 1e-12 (velocities rescaled by the
// engine about a dozen times in between).
void bm_cooling_early_late(benchmark::State& state) {
  Parameters p;
  p.dimension = 2;
  p.particles = 5000;
  p.density = 0.05;
  p.restitution = 0.9;
  p.randomize = Randomization::flux;
  p.relax_collisions_per_particle = 1;
  Engine<2> engine(p);
  engine.relax(p.relax_collisions_per_particle);
  auto rate = [&](std::uint64_t collisions) {
    engine.resume();
    const std::uint64_t c0 = engine.collisions();
    engine.set_collision_limit(c0 + collisions);
    const double cpu0 = thread_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    engine.advance_to(1e300);
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double c = static_cast<double>(engine.collisions() - c0);
    return std::tuple{c / s, c / (thread_cpu_seconds() - cpu0), s};
  };
  for (auto _ : state) {
    const auto [early, early_cpu, s1] = rate(100000);
    const double t_early = engine.temperature();
    engine.resume();
    engine.set_collision_limit(0);
    engine.set_min_temperature(1e-12);
    engine.advance_to(1e300);  // cools (stops at T = 1e-12)
    engine.set_min_temperature(0);
    const double t_late = engine.temperature(), time_late = engine.time();
    const auto [late, late_cpu, s2] = rate(100000);
    state.SetIterationTime(s1 + s2);
    state.counters["early_collisions_per_s"] = early;
    state.counters["early_collisions_per_cpu_s"] = early_cpu;
    state.counters["late_collisions_per_s"] = late;
    state.counters["late_collisions_per_cpu_s"] = late_cpu;
    state.counters["T_after_early"] = t_early;
    state.counters["T_at_late_start"] = t_late;
    state.counters["t_at_late_start"] = time_late;
  }
}
BENCHMARK(bm_cooling_early_late)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
