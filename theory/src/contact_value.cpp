// Enskog factor g2(σ) for disks (Henderson) and spheres (Carnahan–Starling).
#include "molchaos/theory/contact_value.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "molchaos/theory/dimension.hpp"

namespace molchaos::theory {

double contact_value_g2(int dimension, double packing_fraction) {
  require_dimension(dimension);
  if (!(packing_fraction >= 0.0 && packing_fraction < 1.0))
    throw std::invalid_argument("packing_fraction: value " + std::to_string(packing_fraction) +
                                " is outside the allowed range [0, 1)");
  const double eta = packing_fraction;
  if (dimension == 2) return (1.0 - 7.0 * eta / 16.0) / ((1.0 - eta) * (1.0 - eta));
  return (1.0 - 0.5 * eta) / std::pow(1.0 - eta, 3);
}

double contact_value_g2_at_density(int dimension, double density) {
  require_density(dimension, density);
  return contact_value_g2(dimension, packing_fraction(dimension, density));
}

double fluid_limit_packing(int dimension) {
  require_dimension(dimension);
  return dimension == 2 ? 0.700 : 0.494;
}

bool g2_extrapolated(int dimension, double packing_fraction) {
  return packing_fraction > fluid_limit_packing(dimension);
}

}  // namespace molchaos::theory
