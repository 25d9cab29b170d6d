// Enskog factor: the contact value g2(σ) of the pair correlation function of the equilibrium
// hard-sphere fluid, the static correlation that the paper keeps (its eq. 2DCarnahanStarling).
#pragma once

namespace molchaos::theory {

/// g2(σ) at packing fraction η.
/// d = 2: Henderson's form for disks, (1 − 7η/16)/(1 − η)², as printed in the paper.
/// d = 3: Carnahan–Starling, (1 − η/2)/(1 − η)³.
double contact_value_g2(int dimension, double packing_fraction);

/// g2(σ) at reduced density n = N σ^d / V; checks the density range.
double contact_value_g2_at_density(int dimension, double density);

/// The packing fraction where the equilibrium fluid, and with it the fluid equations of state
/// above, ends: 0.700 for disks (the liquid meets liquid–hexatic coexistence; Bernard & Krauth,
/// Phys. Rev. Lett. 107, 155704 (2011)), 0.494 for spheres (freezing; Hoover & Ree, J. Chem.
/// Phys. 49, 3609 (1968)). Beyond it g2(σ), and every Enskog number built on it, is an
/// extrapolation of the fluid branch.
double fluid_limit_packing(int dimension);

/// Whether g2(σ) at this packing fraction lies beyond fluid_limit_packing().
bool g2_extrapolated(int dimension, double packing_fraction);

}  // namespace molchaos::theory
