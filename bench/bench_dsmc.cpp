// Speed of the DSMC method (Google Benchmark; `make bench`): collisions per second and per CPU
// second of the candidate loop at N = 1e5, d = 2 (n = 0.05) and d = 3 (packing fraction 0.1),
// elastic and ε = 0.9, plus candidates per collision (the majorant's rejections) and the
// collisions done (for instructions per collision under
// `valgrind --tool=callgrind build/bench/bench_dsmc --benchmark_min_time=0.001`).
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <numbers>

#include "molchaos/sim/dsmc.hpp"
#include "molchaos/sim/run.hpp"

namespace {

using molchaos::sim::DsmcGas;
using molchaos::sim::Parameters;

// CPU time of this thread (the machine may be shared).
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Each iteration advances the gas by the time in which Enskog's frequency at the current
// temperature gives `collisions` collisions (the cooling gas is rescaled internally).
template <int D>
void time_dsmc(benchmark::State& state, double restitution) {
  Parameters p;
  p.dimension = D;
  p.particles = 100000;
  p.density = D == 2 ? 0.05 : 0.6 / std::numbers::pi;
  p.restitution = restitution;
  p.t_end = 1e300;
  constexpr double collisions = 2e6;
  DsmcGas<D> gas(p, molchaos::sim::contact_value_g2(D, p.density));
  double seconds = 0, cpu_seconds = 0;
  std::uint64_t done = 0, candidates = 0;
  for (auto _ : state) {
    const std::uint64_t c0 = gas.collisions(), k0 = gas.candidates();
    const double omega = molchaos::sim::enskog_collision_frequency(D, p.density, gas.temperature());
    const double t = gas.time() + 2.0 * collisions / (static_cast<double>(p.particles) * omega);
    const double cpu0 = thread_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    gas.advance_to(t);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cpu_seconds += thread_cpu_seconds() - cpu0;
    seconds += wall;
    done += gas.collisions() - c0;
    candidates += gas.candidates() - k0;
    state.SetIterationTime(wall);
  }
  state.counters["collisions_per_s"] = static_cast<double>(done) / seconds;
  state.counters["collisions_per_cpu_s"] = static_cast<double>(done) / cpu_seconds;
  state.counters["candidates_per_collision"] =
      static_cast<double>(candidates) / static_cast<double>(done);
  state.counters["collisions"] = static_cast<double>(done);
  state.counters["final_T"] = gas.temperature();
}

void bm_dsmc_disks(benchmark::State& state) {
  time_dsmc<2>(state, static_cast<double>(state.range(0)) / 100.0);
}
void bm_dsmc_spheres(benchmark::State& state) {
  time_dsmc<3>(state, static_cast<double>(state.range(0)) / 100.0);
}

}  // namespace

// Argument: restitution in percent.
BENCHMARK(bm_dsmc_disks)->Arg(100)->Arg(90)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(bm_dsmc_spheres)->Arg(100)->Arg(90)->UseManualTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
