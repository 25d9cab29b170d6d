// The hydrodynamic block of `molchaos theory` (see the header).
#include "theory_hydrodynamics_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "cli_support.hpp"
#include "molchaos/theory/dimension.hpp"
#include "molchaos/theory/hydrodynamics.hpp"

namespace molchaos::app {

std::shared_ptr<theory::BoxInputs> add_hydrodynamics_options(CLI::App& cmd) {
  auto h = std::make_shared<theory::BoxInputs>();
  cmd.add_option("--particles", h->particles, "particles N of the box (largest shear mode 2π/L)")
      ->transform(integer_in(theory::k_min_box_particles, theory::k_max_box_particles))
      ->capture_default_str();
  cmd.add_option("--growth", h->growth,
                 "level of the largest shear mode's S⊥ (1 in equilibrium) whose time is printed")
      ->transform(real_in(1.0, false, theory::k_max_growth, true))
      ->capture_default_str();
  return h;
}

std::string hydrodynamics_text(const theory::ReportInputs& in, const theory::TheoryReport& r) {
  const auto& c = r.transport;
  const auto& m = r.shear_mode;
  const auto& h = in.box;
  std::string s =
      "\nlinear hydrodynamics of the HCS (Enskog, first Sonine, molecular chaos: b = 0 whatever "
      "--b; rates per collision per particle)\n";
  s += fmt::format(
      "  η*, κ*, μ*, ζ*         {:.6g}, {:.6g}, {:.6g}, {:.6g}   (Garzó–Dufty's reduced units: "
      "η/η0, κ/κ0, nμ/(Tκ0), ζ/ν0; ν0/ω_E = {:.6g})\n",
      c.shear_viscosity, c.thermal_conductivity, c.heat_flux_density, c.cooling_rate,
      c.collision_ratio);
  if (theory::heat_mode_unstable_at_every_wavelength(c))
    s += fmt::format(
        "  critical box L_c = 2π/k⊥  {:.6g} σ   (heat mode: no k∥, the longitudinal modes grow at "
        "every wavelength: the first-Sonine Navier–Stokes description breaks down here)\n",
        theory::critical_box_size(c));
  else
    s += fmt::format("  critical box L_c = 2π/k⊥  {:.6g} σ   (heat mode 2π/k∥: {:.6g} σ)\n",
                     theory::critical_box_size(c),
                     2.0 * std::numbers::pi / theory::critical_heat_wavenumber(c));
  // A box below L_c: the mode decays, but the noise holds its S⊥ at a level above 1, which a
  // growth level below it is reached on the way to.
  if (!(m.rate > 0)) {
    s += fmt::format(
        "  N = {}: box {:.6g} σ, below L_c: the largest shear mode's amplitude decays at {:.6g} "
        "per collision per particle, and the noise holds its S⊥ at {:.6g}\n",
        h.particles, m.box, -m.rate, m.stationary_level);
    if (!std::isfinite(m.collisions))
      s += fmt::format("  its S⊥ never reaches {}\n", theory::exact_text(h.growth));
  }
  if (m.rate > 0)
    s += fmt::format(
        "  N = {}: box {:.6g} σ, the largest shear mode's amplitude grows at {:.6g} per collision "
        "per particle (its energy S⊥ at twice that, once the decaying modes have died out)\n",
        h.particles, m.box, m.rate);
  // A box of a few mean free paths: the printed rate is the Navier–Stokes formula's, outside
  // the range where it describes the gas.
  if (theory::beyond_hydrodynamics(c, m.wavenumber))
    s += fmt::format(
        "  note: this mode has kℓ = {:.3g} (ℓ = {:.3g} σ, about a mean free path); Navier–Stokes "
        "hydrodynamics holds for kℓ ≪ 1 and drops terms of order (kℓ)², so above kℓ = {} its "
        "rates for this box are not predictions\n",
        theory::reduced_wavenumber(c, m.wavenumber), c.length_unit,
        theory::k_hydrodynamic_k_length_limit);
  if (!std::isfinite(m.collisions)) return s;
  s += fmt::format(
      "  its S⊥ reaches {} after {:.6g} collisions per particle, t = {} "
      "(ln t = {:.4g}) on Haff's law\n",
      theory::exact_text(h.growth), m.collisions,
      std::isfinite(m.time) ? fmt::format("{:.6g}", m.time) : "beyond the largest double",
      m.log_time);
  return s;
}

}  // namespace molchaos::app
