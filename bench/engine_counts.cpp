// Deterministic work counts of the event-driven engine, for a shared machine whose wall-clock
// rates drift by tens of percent within minutes. Run under callgrind by engine_counts.sh: the
// setup (placement, relaxation) is not collected, only the timed phase of each case of
// bench_engine (engine_cases.hpp): the paper's case whole, the 3D cases over 5e5 of their 2e6
// collisions. Without valgrind the toggles do nothing and the program just runs the cases.
#include <cstdint>
#include <cstdio>
#include <string>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_TOGGLE_COLLECT
#endif

#include "engine_cases.hpp"
#include "molchaos/sim/engine.hpp"

namespace {

using molchaos::sim::Engine;
using molchaos::sim::Parameters;

template <int D>
void run(const Parameters& p, std::uint64_t collisions) {
  Engine<D> engine(p);
  engine.relax(p.relax_collisions_per_particle);
  const std::uint64_t c0 = engine.collisions(), e0 = engine.events();
  engine.set_collision_limit(c0 + collisions);
  CALLGRIND_TOGGLE_COLLECT;
  engine.advance_to(1e300);
  CALLGRIND_TOGGLE_COLLECT;
  std::printf("collisions %llu events %llu\n",
              static_cast<unsigned long long>(engine.collisions() - c0),
              static_cast<unsigned long long>(engine.events() - e0));
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "";
  if (which == "paper") {  // bm_paper_case/shuffle:0
    run<2>(molchaos::bench::paper_case(molchaos::sim::Randomization::none), 200000);
  } else if (which == "spheres10" || which == "spheres40") {  // bm_spheres
    run<3>(molchaos::bench::spheres_case(which == "spheres10" ? 0.1 : 0.4), 500000);
  } else {
    std::fprintf(stderr, "usage: engine_counts paper|spheres10|spheres40\n");
    return 2;
  }
  return 0;
}
