// The hydrodynamic block of `molchaos theory` (see the header).
#include "theory_hydrodynamics_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "cli_support.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/hydrodynamics.hpp"

namespace molchaos::app {
namespace {

nlohmann::json finite_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

struct LargestShearMode {
  double box = 0, wavenumber = 0, rate = 0, collisions = 0, time = 0;
  double log_time = 0;  ///< ln t, finite where t overflows a double
};

// τ collisions per particle after time t of Haff's law: τ = ω_E(T0) τ0 ln(1 + t/τ0), since
// ω_E ∝ √T = √T0/(1 + t/τ0); inverted for t.
LargestShearMode largest_shear_mode(const theory::TransportCoefficients& c, int dimension,
                                    double restitution, double density,
                                    const HydrodynamicsOptions& h) {
  LargestShearMode m;
  // (N/n)^(1/d) as N^(1/d) / n^(1/d): the quotient N/n overflows for n below about 1e-300.
  m.box = std::pow(static_cast<double>(h.particles), 1.0 / dimension) /
          std::pow(density, 1.0 / dimension);
  m.wavenumber = 2.0 * std::numbers::pi / m.box;
  m.rate = theory::shear_mode_rate(c, m.wavenumber);
  m.collisions = theory::collisions_to_reach(c, m.wavenumber, h.growth);
  theory::CoolingInputs in;
  in.dimension = dimension;
  in.density = density;
  in.restitution = restitution;
  const auto p = theory::predict_cooling(in);
  const double scale = p.enskog_collision_frequency * p.tau0.value;
  const bool finite = std::isfinite(m.collisions) && std::isfinite(scale);
  m.time = finite ? p.tau0.value * std::expm1(m.collisions / scale)
                  : std::numeric_limits<double>::infinity();
  m.log_time = finite ? theory::log_time_after_collisions(m.collisions, p.tau0.value,
                                                          p.enskog_collision_frequency)
                      : std::numeric_limits<double>::infinity();
  return m;
}

}  // namespace

std::shared_ptr<HydrodynamicsOptions> add_hydrodynamics_options(CLI::App& cmd) {
  auto h = std::make_shared<HydrodynamicsOptions>();
  cmd.add_option("--particles", h->particles, "particles N of the box (largest shear mode 2π/L)")
      ->transform(integer_in(2, 100000000))
      ->capture_default_str();
  cmd.add_option("--growth", h->growth,
                 "level of the largest shear mode's S⊥ (1 in equilibrium) whose time is printed")
      ->transform(real_in(1.0, false, 1e12, true))
      ->capture_default_str();
  return h;
}

void add_hydrodynamics_json(nlohmann::json& j, int dimension, double restitution, double density,
                            const HydrodynamicsOptions& h) {
  const auto c = theory::transport_coefficients({dimension, density, restitution, std::nullopt});
  const auto m = largest_shear_mode(c, dimension, restitution, density, h);
  j["critical_box_size"] = finite_or_null(theory::critical_box_size(c));
  j["critical_shear_wavenumber"] = theory::critical_shear_wavenumber(c);
  // Where the longitudinal modes grow at every k no k∥ exists: null, and the flag says why (a
  // 0 read as 2π/k∥ = ∞ would say the opposite, never unstable).
  const bool every_wavelength = theory::heat_mode_unstable_at_every_wavelength(c);
  j["critical_heat_wavenumber"] = every_wavelength
                                      ? nlohmann::json(nullptr)
                                      : nlohmann::json(theory::critical_heat_wavenumber(c));
  j["heat_mode_unstable_at_every_wavelength"] = every_wavelength;
  j["transport"] = {
      {"cooling_rate", c.cooling_rate},           {"pressure", c.pressure},
      {"compressibility", c.compressibility},     {"shear_viscosity", c.shear_viscosity},
      {"bulk_viscosity", c.bulk_viscosity},       {"thermal_conductivity", c.thermal_conductivity},
      {"heat_flux_density", c.heat_flux_density}, {"length_unit", c.length_unit},
      {"collision_ratio", c.collision_ratio}};
  j["largest_shear_mode"] = {{"particles", h.particles},
                             {"box", m.box},
                             {"wavenumber", m.wavenumber},
                             {"rate_per_collision", m.rate},
                             {"growth", h.growth},
                             {"collisions_per_particle", finite_or_null(m.collisions)},
                             {"time", finite_or_null(m.time)},
                             {"log_time", finite_or_null(m.log_time)}};
}

std::string hydrodynamics_text(int dimension, double restitution, double density,
                               const HydrodynamicsOptions& h) {
  const auto c = theory::transport_coefficients({dimension, density, restitution, std::nullopt});
  const auto m = largest_shear_mode(c, dimension, restitution, density, h);
  std::string s =
      "\nlinear hydrodynamics of the HCS (Enskog, first Sonine; rates per collision "
      "per particle)\n";
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
  if (!(m.rate > 0)) {  // a box below L_c: the mode decays, the gas stays homogeneous
    s += fmt::format(
        "  N = {}: box {:.6g} σ, below L_c: the largest shear mode's amplitude decays at {:.6g} "
        "per collision per particle, and S⊥ never reaches {:g}\n",
        h.particles, m.box, -m.rate, h.growth);
    return s;
  }
  s += fmt::format(
      "  N = {}: box {:.6g} σ, the largest shear mode's amplitude grows at {:.6g} per collision "
      "per particle (its energy S⊥ at twice that, once the decaying modes have died out)\n",
      h.particles, m.box, m.rate);
  s += fmt::format(
      "  its S⊥ reaches {:g} after {:.6g} collisions per particle, t = {} "
      "(ln t = {:.4g}) on Haff's law\n",
      h.growth, m.collisions,
      std::isfinite(m.time) ? fmt::format("{:.6g}", m.time) : "beyond the largest double",
      m.log_time);
  return s;
}

}  // namespace molchaos::app
