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

}  // namespace molchaos::theory
