// Geometry of d-dimensional hard spheres (σ = 1): packing fraction, close packing, unit sphere,
// and the argument checks shared by the theory functions.
#pragma once

#include <charconv>
#include <numbers>
#include <stdexcept>
#include <string>

namespace molchaos::theory {

/// x in the shortest form that reads back as x: the numbers of an error message, whose value and
/// bounds would otherwise round to the same digits ("value 0.67121596 is outside [-2, 0.671216)").
inline std::string exact_text(double x) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, x);
  return std::string(text, result.ptr);
}

/// Throws std::invalid_argument naming `dimension` and its allowed values unless d ∈ {2, 3}.
inline void require_dimension(int dimension) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: value " + std::to_string(dimension) +
                                " is not allowed; allowed values 2 or 3");
}

/// Volume of a particle of diameter σ = 1: π/4 (disk), π/6 (sphere).
inline double particle_volume(int dimension) {
  require_dimension(dimension);
  return dimension == 2 ? std::numbers::pi / 4.0 : std::numbers::pi / 6.0;
}

/// Packing fraction η = n · v_particle for reduced density n = N σ^d / V.
inline double packing_fraction(int dimension, double density) {
  return density * particle_volume(dimension);
}

/// Reduced density of the densest packing: hexagonal disks n = 2/√3, fcc spheres n = √2.
inline double close_packing_density(int dimension) {
  require_dimension(dimension);
  return dimension == 2 ? 2.0 / std::numbers::sqrt3 : std::numbers::sqrt2;
}

/// Surface area |S^{d-1}| of the unit sphere: 2π (d = 2), 4π (d = 3).
inline double unit_sphere_area(int dimension) {
  require_dimension(dimension);
  return dimension == 2 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi;
}

/// Throws std::invalid_argument naming `name` and the allowed range unless lo < x ≤ hi
/// (or lo < x < hi when `hi_open`).
void require_in_range(const std::string& name, double x, double lo, double hi, bool hi_open);

/// Checks restitution ∈ (0, 1] and density ∈ (0, close packing).
void require_restitution(double restitution);
void require_density(int dimension, double density);

}  // namespace molchaos::theory
