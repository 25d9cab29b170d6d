// Flow-field panels from snapshots (see the header).
#include "molchaos/validation/flow_field.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "molchaos/sim/run.hpp"
#include "molchaos/validation/structure_factor.hpp"

namespace molchaos::validation {

FlowFieldData flow_field_data(const FlowFieldSpec& spec) {
  FlowFieldData out;
  out.rows.resize(spec.log_times.size());
  for (const auto& mode_name : spec.modes) {
    const auto mode = sim::parse_randomization(mode_name);
    if (!mode) throw std::invalid_argument("modes: unknown randomization " + mode_name);
    sim::Parameters p;
    p.dimension = 2;
    p.particles = spec.particles;
    p.density = spec.density;
    p.restitution = spec.restitution;
    p.randomize = *mode;
    p.seed = spec.seed;
    for (double l : spec.log_times) p.snapshot_times.push_back(std::exp(l));
    p.t_end = p.snapshot_times.back();
    const sim::RunResult r = sim::run(p);
    out.column_titles.push_back(mode_name == "none" ? "original gas" : mode_name + " shuffle");
    for (std::size_t i = 0; i < r.snapshots.size() && i < out.rows.size(); ++i) {
      const CoarseField f = coarse_grain(r.snapshots[i], 2, spec.cells);
      const double thermal = std::sqrt(f.temperature);
      const double mean = static_cast<double>(spec.particles) / (spec.cells * spec.cells);
      FlowFieldPanel panel;
      panel.title = fmt::format("{}, ln t = {:g}", out.column_titles.back(), spec.log_times[i]);
      panel.box = r.snapshots[i].box;
      panel.cells = spec.cells;
      const auto w = vorticity(f);
      for (std::size_t c = 0; c < f.number.size(); ++c) {
        panel.relative_density.push_back(f.number[c] / mean);
        panel.vx.push_back(f.velocity[2 * c] / thermal);
        panel.vy.push_back(f.velocity[2 * c + 1] / thermal);
        panel.vorticity.push_back(w[c] / thermal);
      }
      out.rows[i].push_back(std::move(panel));
    }
  }
  return out;
}

}  // namespace molchaos::validation
