// Flow-field panels from snapshots (see the header).
#include "molchaos/validation/flow_field.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <stdexcept>

#include "molchaos/sim/result.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/validation/structure_factor.hpp"

namespace molchaos::validation {

FlowFieldPanel flow_field_panel(const sim::Snapshot& snapshot, int cells, std::string title) {
  const CoarseField f = coarse_grain(snapshot, 2, cells);
  const double thermal = std::sqrt(f.temperature);
  const double particles = static_cast<double>(snapshot.positions.size() / 2);
  const double mean = particles / (cells * cells);
  FlowFieldPanel panel;
  panel.title = std::move(title);
  panel.box = snapshot.box;
  panel.cells = cells;
  // A cell of `mean` particles: its count Poisson, each velocity component of variance T/mean;
  // the vorticity's central differences (structure_factor.cpp) add four such components over
  // (2 × cell width)².
  panel.density_noise = 1.0 / std::sqrt(mean);
  panel.vorticity_noise = 1.0 / (std::sqrt(mean) * f.cell_width);
  const auto w = vorticity(f);
  for (std::size_t c = 0; c < f.number.size(); ++c) {
    panel.relative_density.push_back(f.number[c] / mean);
    panel.vx.push_back(f.velocity[2 * c] / thermal);
    panel.vy.push_back(f.velocity[2 * c + 1] / thermal);
    panel.vorticity.push_back(w[c] / thermal);
  }
  return panel;
}

// n(r)/n̄ = 1 + (2/N) Σ_{k in half space} Re(ρ_k e^{−ik·r}), ρ_k = Σ_i e^{ik·r_i}; the velocity
// likewise from j_k = Σ_i v_i e^{ik·r_i} (divided by n̄, the linear order), the vorticity
// ∂x u_y − ∂y u_x from the same sum differentiated term by term.
FlowFieldPanel long_wave_panel(const sim::Snapshot& snapshot, int cells, int max_norm2,
                               std::string title) {
  const std::size_t n = snapshot.positions.size() / 2;
  const double count = static_cast<double>(n);
  double v2 = 0;
  for (double v : snapshot.velocities) v2 += v * v;
  const double thermal = std::sqrt(v2 / (2 * count));
  const double unit = 2 * M_PI / snapshot.box;
  struct Mode {
    double kx, ky;
    std::complex<double> rho, jx, jy;
  };
  std::vector<Mode> modes;
  const int r = static_cast<int>(std::sqrt(static_cast<double>(max_norm2)));
  for (int mx = 0; mx <= r; ++mx)
    for (int my = -r; my <= r; ++my) {
      if (mx * mx + my * my == 0 || mx * mx + my * my > max_norm2 || (mx == 0 && my < 0)) continue;
      Mode m{unit * mx, unit * my, 0, 0, 0};
      for (std::size_t i = 0; i < n; ++i) {
        const double phase =
            m.kx * snapshot.positions[2 * i] + m.ky * snapshot.positions[2 * i + 1];
        const std::complex<double> e{std::cos(phase), std::sin(phase)};
        m.rho += e;
        m.jx += snapshot.velocities[2 * i] * e;
        m.jy += snapshot.velocities[2 * i + 1] * e;
      }
      modes.push_back(m);
    }
  FlowFieldPanel panel;
  panel.title = std::move(title);
  panel.box = snapshot.box;
  panel.cells = cells;
  // Without correlations ⟨|ρ_k|²⟩ = N and ⟨|j_k,a|²⟩ = N T, independent between modes and
  // components, and Re(z e^{−ik·r}) of such a z has half its variance: each mode adds 2/N to the
  // variance of the relative density and 2k²/N to that of the vorticity (in units of √T/σ).
  double squared_wavenumbers = 0;
  for (const auto& m : modes) squared_wavenumbers += m.kx * m.kx + m.ky * m.ky;
  panel.density_noise = std::sqrt(2.0 * static_cast<double>(modes.size()) / count);
  panel.vorticity_noise = std::sqrt(2.0 * squared_wavenumbers / count);
  const double w = snapshot.box / cells;
  const std::complex<double> i_unit{0, 1};
  for (int y = 0; y < cells; ++y)
    for (int x = 0; x < cells; ++x) {
      const double px = (x + 0.5) * w, py = (y + 0.5) * w;
      double rho = 0, ux = 0, uy = 0, curl = 0;
      for (const auto& m : modes) {
        const std::complex<double> e = std::exp(-i_unit * (m.kx * px + m.ky * py));
        rho += std::real(m.rho * e);
        ux += std::real(m.jx * e);
        uy += std::real(m.jy * e);
        curl += std::real(-i_unit * (m.kx * m.jy - m.ky * m.jx) * e);
      }
      panel.relative_density.push_back(1.0 + 2.0 * rho / count);
      panel.vx.push_back(2.0 * ux / count / thermal);
      panel.vy.push_back(2.0 * uy / count / thermal);
      panel.vorticity.push_back(2.0 * curl / count / thermal);
    }
  return panel;
}

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
    for (std::size_t i = 0; i < r.snapshots.size() && i < out.rows.size(); ++i)
      out.rows[i].push_back(flow_field_panel(
          r.snapshots[i], spec.cells,
          fmt::format("{}, ln t = {:g}", out.column_titles.back(), spec.log_times[i])));
  }
  return out;
}

}  // namespace molchaos::validation
