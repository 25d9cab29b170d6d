// Deterministic work counts of the event-driven engine, for a shared machine whose wall-clock
// rates drift by tens of percent within minutes. Run under callgrind by engine_counts.sh: the
// setup (placement, relaxation) is not collected, only the timed phase of each case of
// bench_engine (engine_cases.hpp): the paper's case whole, the 3D cases over 5e5 of their 2e6
// collisions. The paper's case also with the observers of a real run: paper_series samples the
// temperature series on run()'s time grid (t_end = 1e6), paper_contacts adds contact statistics.
// disks1e3 .. disks1e6: the first 2e5 collisions of bm_disks at n = 0.05 with N = 1e3 .. 1e6, whose
// data grow from well inside a core's L2 cache (N = 1e3: 0.2 MB) to far beyond its last level.
// Without valgrind the toggles do nothing and the program just runs the cases.
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <type_traits>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_TOGGLE_COLLECT
#endif

#include "engine_cases.hpp"
#include "molchaos/sim/engine.hpp"
#include "molchaos/sim/run.hpp"

namespace {

using molchaos::sim::Engine;
using molchaos::sim::Parameters;

// series: sample at run()'s sample times, as run() does, until the collision limit stops the run.
template <int D, class Observer = molchaos::sim::NoObserver>
void run(const Parameters& p, std::uint64_t collisions, bool series = false) {
  Engine<D, Observer> engine(p);
  engine.relax(p.relax_collisions_per_particle);
  const std::uint64_t c0 = engine.collisions(), e0 = engine.events();
  engine.set_collision_limit(c0 + collisions);
  double sum = 0;  // of the sampled temperatures, so that the samples are used
  CALLGRIND_TOGGLE_COLLECT;
  if (series) {
    for (const double t : molchaos::sim::sample_times(p)) {
      if (engine.advance_to(t) == Engine<D, Observer>::Status::stopped) break;
      sum += engine.sample().temperature;
      if constexpr (std::is_same_v<Observer, molchaos::sim::ContactStatistics>)
        sum += static_cast<double>(engine.observer().take().count);
    }
  } else {
    engine.advance_to(1e300);
  }
  CALLGRIND_TOGGLE_COLLECT;
  std::printf("collisions %llu events %llu\n",
              static_cast<unsigned long long>(engine.collisions() - c0),
              static_cast<unsigned long long>(engine.events() - e0));
  if (series) std::fprintf(stderr, "sum of samples %g\n", sum);
}

// The bm_disks cases at n = 0.05 by name: N from 1e3 to 1e6.
const std::map<std::string, std::int32_t> k_disks = {
    {"disks1e3", 1000}, {"disks1e4", 10000}, {"disks1e5", 100000}, {"disks1e6", 1000000}};

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "";
  using molchaos::sim::Randomization;
  if (which == "paper") {  // bm_paper_case/shuffle:0
    run<2>(molchaos::bench::paper_case(Randomization::none), 200000);
  } else if (which == "paper_series" || which == "paper_contacts") {
    Parameters p = molchaos::bench::paper_case(Randomization::none);
    p.t_end = 1e6;
    if (which == "paper_series")
      run<2>(p, 200000, true);
    else
      run<2, molchaos::sim::ContactStatistics>(p, 200000, true);
  } else if (const auto disks = k_disks.find(which); disks != k_disks.end()) {  // bm_disks
    run<2>(molchaos::bench::disks_case(disks->second, 0.05), 200000);
  } else if (which == "spheres10" || which == "spheres40") {  // bm_spheres
    run<3>(molchaos::bench::spheres_case(which == "spheres10" ? 0.1 : 0.4), 500000);
  } else {
    std::fprintf(stderr,
                 "usage: engine_counts paper|paper_series|paper_contacts|disks1e3|disks1e4|"
                 "disks1e5|disks1e6|spheres10|spheres40\n");
    return 2;
  }
  return 0;
}
