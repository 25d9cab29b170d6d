// Linear hydrodynamics of the homogeneous cooling state (HCS) of inelastic hard disks/spheres:
// Enskog transport coefficients in the first Sonine approximation, the critical wavenumbers of
// the shear and heat modes, and the growth of each Fourier mode counted in collisions per particle.
//
// Sources: Brey, Dufty, Kim & Santos, PRE 58, 4638 (1998) (dilute coefficients, scaled linear
// hydrodynamics); Garzó & Dufty, PRE 59, 5895 (1999) and Garzó, PRE 72, 021106 (2005) (Enskog
// density corrections, d dimensions); Goldhirsch & Zanetti, PRL 70, 1619 (1993) and McNamara &
// Young, PRE 53, 5089 (1996) (the shear and clustering instabilities). Elastic limits: Gass,
// J. Chem. Phys. 54, 1898 (1971) for disks, Chapman & Cowling ch. 16 for spheres.
//
// Units: σ = m = k_B = 1, T = m⟨v²⟩/d. Reduced coefficients refer to the dilute elastic ones:
// η0 = (d+2)/8 · Γ(d/2) π^{−(d−1)/2} √T, κ0 = d(d+2)/(2(d−1)) η0, ν0 = nT/η0. Lengths are in
// ℓ = √T/ν0 = η0(T)/(n√T) (independent of T), rates per s with ds = ν0 dt; since ν0, the Enskog
// collision frequency ω_E and the cooling rate all scale with √T, rates per s are constant in
// the cooling gas and convert to rates per collision per particle τ (dτ = ω_E dt) by ν0/ω_E.
#pragma once

#include <optional>

namespace molchaos::theory {

struct HydrodynamicInputs {
  int dimension = 2;
  double density = 0.05;     ///< n = Nσ^d/V
  double restitution = 0.9;  ///< ε (α in the sources)
  std::optional<double> a2;  ///< default: first-Sonine a2(ε) (sonine.hpp)
};

/// Reduced Enskog coefficients of the HCS at one state point.
struct TransportCoefficients {
  int dimension = 2;
  double packing_fraction = 0;  ///< φ
  double g2 = 0;                ///< χ = g2(σ) (contact_value.hpp)
  double a2 = 0;
  double cooling_rate = 0;          ///< ζ* = ζ/ν0
  double pressure = 0;              ///< p* = p/(nT)
  double compressibility = 0;       ///< C = ∂(n p*)/∂n; 1/C = S(k → 0) of the elastic fluid
  double shear_viscosity = 0;       ///< η* = η/η0
  double bulk_viscosity = 0;        ///< γ* = γ/η0
  double thermal_conductivity = 0;  ///< κ* = κ/κ0
  double heat_flux_density = 0;     ///< μ* = nμ/(Tκ0) (zero for elastic collisions)
  double length_unit = 0;           ///< ℓ in σ
  double collision_ratio = 0;       ///< ν0/ω_E: rates per s times this are rates per τ
};

TransportCoefficients transport_coefficients(const HydrodynamicInputs& inputs);

/// Elastic Enskog closed forms, η/η0 and κ/κ0 (Gass 1971 for d = 2; Chapman–Cowling's first
/// approximation for d = 3), with χ = g2 at packing fraction φ.
double enskog_elastic_shear_viscosity(int dimension, double packing_fraction, double g2);
double enskog_elastic_thermal_conductivity(int dimension, double packing_fraction, double g2);

/// Growth rate per collision per particle of the amplitude of a transverse velocity mode of
/// wavenumber k (in 1/σ) relative to the thermal velocity: (ζ*/2 − η* (kℓ)²)·ν0/ω_E.
double shear_mode_rate(const TransportCoefficients& c, double wavenumber);

/// Largest real part of the eigenvalues of the longitudinal (density, velocity, temperature)
/// linear system at wavenumber k, per collision per particle.
double longitudinal_mode_rate(const TransportCoefficients& c, double wavenumber);

/// Critical wavenumbers in 1/σ: shear modes with k < k⊥ and the heat mode with k < k∥ grow.
/// 0 where no such k exists: for elastic collisions (nothing grows), and for the heat mode also
/// where heat_mode_unstable_at_every_wavelength (it grows at every k: check that first).
double critical_shear_wavenumber(const TransportCoefficients& c);
double critical_heat_wavenumber(const TransportCoefficients& c);

/// True where the longitudinal modes grow at every wavelength (longitudinal_mode_rate > 0 for
/// all k), so no k∥ exists: the determinant of the longitudinal matrix never vanishes (the heat
/// flux coefficient μ* outweighs κ*, at strong dissipation: ε ≲ 0.35 for disks and ε ≲ 0.19 for
/// spheres at n = 0.05). There
/// the first-Sonine Navier–Stokes description itself breaks down.
bool heat_mode_unstable_at_every_wavelength(const TransportCoefficients& c);

/// L_c = 2π/k⊥ in σ (+inf for elastic collisions): a periodic box of side L > L_c has an
/// unstable shear mode.
double critical_box_size(const TransportCoefficients& c);

/// Navier–Stokes order holds for kℓ ≪ 1 (ℓ = length_unit, about a mean free path); the terms it
/// drops are of relative order (kℓ)². Beyond this kℓ a predicted rate is reported with a note.
inline constexpr double k_hydrodynamic_k_length_limit = 0.5;

/// kℓ of a mode of wavenumber k (in 1/σ).
inline double reduced_wavenumber(const TransportCoefficients& c, double wavenumber) {
  return wavenumber * c.length_unit;
}

/// Whether a mode of wavenumber k lies beyond that limit, where a rate is printed with a note.
inline bool beyond_hydrodynamics(const TransportCoefficients& c, double wavenumber) {
  return reduced_wavenumber(c, wavenumber) > k_hydrodynamic_k_length_limit;
}

/// Transverse velocity structure factor S⊥(k, τ) = ⟨|j⊥(k)|²⟩/(N T) after τ collisions per
/// particle from an equilibrium start S⊥ = 1, by linear fluctuating hydrodynamics.
double transverse_structure_factor(const TransportCoefficients& c, double wavenumber, double tau);

/// The level S⊥(k, τ → ∞) = a/|λ| at which the noise holds a decaying transverse mode (λ < 0,
/// a box below L_c): above 1 out of equilibrium, since the cooling gas's thermal noise decays
/// more slowly than the mode; +inf where the mode grows.
double stationary_transverse_structure_factor(const TransportCoefficients& c, double wavenumber);

/// Collisions per particle until S⊥(k, τ) reaches `level` (> 1); +inf if it never does.
double collisions_to_reach(const TransportCoefficients& c, double wavenumber, double level);

}  // namespace molchaos::theory
