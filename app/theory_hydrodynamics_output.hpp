// The hydrodynamic block of `molchaos theory`: the critical box size of the homogeneous cooling
// state and the growth of the largest shear mode of a box of N particles (theory/hydrodynamics).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace molchaos::app {

struct HydrodynamicsOptions {
  std::int64_t particles = 5000;  ///< box side L = (N/n)^{1/d}
  double growth = 10.0;           ///< level of S⊥ at the largest shear mode (1 at equilibrium)
};

/// Adds --particles and --growth to the theory command.
std::shared_ptr<HydrodynamicsOptions> add_hydrodynamics_options(CLI::App& cmd);

/// Fills critical_box_size (σ), the critical wavenumbers, the transport coefficients and the
/// largest shear mode's growth into the JSON document `j`. critical_heat_wavenumber is null where
/// no k∥ exists because the longitudinal modes grow at every wavelength
/// (heat_mode_unstable_at_every_wavelength: true); largest_shear_mode.log_time is ln t, finite
/// where time overflows a double (null there).
void add_hydrodynamics_json(nlohmann::json& j, int dimension, double restitution, double density,
                            const HydrodynamicsOptions& h);

/// The same as text lines.
std::string hydrodynamics_text(int dimension, double restitution, double density,
                               const HydrodynamicsOptions& h);

}  // namespace molchaos::app
