// Flow energy's share of T in the homogeneous stage (see the header).
#include "molchaos/validation/flow_energy.hpp"

#include <cmath>

#include "molchaos/sim/result.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/validation/structure_factor.hpp"
#include "molchaos/validation/sweep.hpp"

namespace molchaos::validation {

std::vector<FlowEnergyPoint> flow_energy_study(const FlowEnergySpec& spec) {
  std::vector<FlowEnergyPoint> out;
  for (double n : spec.densities)
    for (double e : spec.restitutions) {
      theory::CoolingInputs in;
      in.dimension = 2;
      in.density = n;
      in.restitution = e;
      const double tau0 = theory::predict_cooling(in).tau0.value;
      double sum = 0, sum2 = 0;
      for (int r = 0; r < spec.runs; ++r) {
        sim::Parameters p;
        p.dimension = 2;
        p.particles = spec.particles;
        p.density = n;
        p.restitution = e;
        p.seed = derive_seed(spec.base_seed, static_cast<std::uint64_t>(r));
        for (double x : spec.times_in_tau0) p.snapshot_times.push_back(x * tau0);
        p.t_end = p.snapshot_times.back();
        const sim::RunResult result = sim::run(p);
        double f = 0;
        for (const auto& snap : result.snapshots) {
          const CoarseField c = coarse_grain(snap, 2, spec.cells);
          // sampling noise of uncorrelated velocities: T·(occupied cells)/N (structure_factor.hpp)
          f += (c.flow_temperature -
                c.temperature * c.occupied_cells / static_cast<double>(spec.particles)) /
               c.temperature;
        }
        f /= static_cast<double>(result.snapshots.size());
        sum += f;
        sum2 += f * f;
      }
      const double m = sum / spec.runs;
      out.push_back(
          {n, e, {m, std::sqrt(std::max(0.0, sum2 / spec.runs - m * m) / (spec.runs - 1))}});
    }
  return out;
}

}  // namespace molchaos::validation
