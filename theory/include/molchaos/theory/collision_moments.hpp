// The collision moments μ_p of the Enskog–Boltzmann collision integral with the paper's
// correlated two-particle distribution at contact (its Eqs. (17), (18), (20)),
// evaluated by quadrature of the defining integral, and their expansion in a2, a3 and b.
//
//   μ_p = −½ ∫dc1 ∫dc2 ∫de Θ(−c12·e)|c12·e| f̃(c1) f̃(c2) [1 + b(κ(c1·e)(c2·e) − c1·c2)]
//         × Δ(c1^p + c2^p)
//
// f̃(c) = π^{−d/2} e^{−c²}[1 + a2 S2(c²) + a3 S3(c²)], κ the dyad factor (3 as printed; d makes
// the dyad traceless in d dimensions), Δ the change of c1^p + c2^p in a collision with
// restitution ε, computed by applying the collision rule. g2(σ) is kept outside μ_p, as in the
// paper's Eq. (22).
//
// Reduction (derived in doc/theory.md): e is fixed along x by rotational invariance (factor
// |S^{d−1}|); c1 = C + g/2, c2 = C − g/2 (unit Jacobian); the centre-of-mass velocity C enters
// only as a polynomial times e^{−2C²} and is summed by a Gauss–Hermite rule that is exact for it;
// what remains is a polynomial in u² and |g⊥|² (u = −g·e) times Gaussians, integrated exactly by
// Gauss–Laguerre rules (default) or by nested GSL adaptive QAGIU (the independent check).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "molchaos/theory/estimate.hpp"
#include "molchaos/theory/paper_constants.hpp"

namespace molchaos::theory {

/// gauss: fixed Gauss–Hermite × Gauss–Laguerre product rules of the exact order; the error
/// estimate is the difference to the rules one order higher plus a rounding bound.
/// adaptive: nested GSL QAGIU to `relative_tolerance`; its own error estimate.
enum class QuadratureMethod { gauss, adaptive };

/// Range of the adaptive quadrature's relative tolerance: below 1e-13 QAGIU cannot meet it in
/// double precision, above 1e-2 the result is no longer worth the name.
inline constexpr double k_min_relative_tolerance = 1e-13;
inline constexpr double k_max_relative_tolerance = 1e-2;

struct QuadratureOptions {
  QuadratureMethod method = QuadratureMethod::gauss;
  double relative_tolerance = 1e-10;  ///< adaptive: requested relative accuracy of each integral
  int hermite_order = 0;   ///< Gauss–Hermite points per C component; 0 = the exact order
  int laguerre_order = 0;  ///< gauss: Gauss–Laguerre points in u²/2 and |g⊥|²/2; 0 = exact
  std::size_t workspace_intervals = 2000;  ///< adaptive: GSL workspace size
};

/// The shape of the pair distribution at contact: Sonine coefficients and correlation b.
struct PairShape {
  double a2 = 0.0;
  double a3 = 0.0;
  double b = 0.0;
};

/// μ_p(a2, a3, b; ε) of the full (non-linearised) integrand. p ∈ {2, 4, 6}.
Estimate collision_moment(int dimension, int p, double restitution, const PairShape& shape,
                          double dyad_factor, const QuadratureOptions& options = {});

/// μ_p(a2, b; ε) with a3 = 0.
inline Estimate collision_moment(int dimension, int p, double restitution, double a2, double b,
                                 double dyad_factor, const QuadratureOptions& options = {}) {
  return collision_moment(dimension, p, restitution, PairShape{a2, 0.0, b}, dyad_factor, options);
}

/// μ2 with the printed dyad factor.
inline Estimate mu2(int dimension, double restitution, double a2, double b,
                    const QuadratureOptions& options = {}) {
  return collision_moment(dimension, 2, restitution, a2, b, k_paper_dyad_factor, options);
}

/// One term a2^i a3^j b^k of μ_p = μ_p(0,0,0; ε)(1 + Σ coefficient · a2^i a3^j b^k). The
/// integrand is a polynomial of degree 2 in (a2, a3) and 1 in b, so the terms are the whole
/// expansion.
struct ExpansionTerm {
  std::string name;  ///< "a2", "a2^2", "b", "a2*b", "a2^2*b", and with a3 "a3", "a2*a3", ...
  int a2_power = 0;
  int b_power = 0;
  int a3_power = 0;
  Estimate integral;     ///< the term's integral (unnormalised)
  Estimate coefficient;  ///< integral / μ_p(0,0), sign included, with propagated error
};

struct ExpansionTable {
  int dimension = 2;
  int moment = 2;
  double restitution = 0.0;
  double dyad_factor = k_paper_dyad_factor;
  double relative_tolerance = 0.0;
  Estimate base;  ///< μ_p(0, 0; ε)
  std::vector<ExpansionTerm> terms;
  std::size_t integrand_evaluations = 0;

  [[nodiscard]] const ExpansionTerm& term(const std::string& name) const;
  /// μ_p / μ_p(0,0) assembled from the coefficients.
  [[nodiscard]] double ratio(double a2, double b) const;
  [[nodiscard]] double ratio(const PairShape& shape) const;
  /// The same with the propagated error of the coefficients, the rounding of the sum, and an
  /// uncertainty `a2_error` of shape.a2 carried through ∂ratio/∂a2.
  [[nodiscard]] Estimate ratio_estimate(const PairShape& shape, double a2_error = 0.0) const;
};

/// Which Sonine terms the expansion carries: a2 and b only (the paper's ansatz), or a3 too.
enum class SonineTerms { a2, a2_a3 };

/// The expansion coefficients of μ_p by quadrature (all terms in one pass of the Gauss rules;
/// one adaptive integral per term with QuadratureMethod::adaptive).
ExpansionTable expand_collision_moment(int dimension, int p, double restitution, double dyad_factor,
                                       const QuadratureOptions& options = {},
                                       SonineTerms terms = SonineTerms::a2);

/// a2(ε) of the first Sonine approximation obtained from quadrature: the moment equation
/// μ4 = (d + 2)(1 + a2) μ2 of the scaled homogeneous cooling state, with μ2, μ4 linearised in a2.
Estimate a2_from_moments(int dimension, double restitution, const QuadratureOptions& options = {});

/// Averages over colliding pairs at contact. With the ansatz of Eq. (17) the collision-rate
/// weighted mean of the dyad D = κ(c1·e)(c2·e) − c1·c2 is
///     ⟨D⟩_coll(b) = (J_D + b J_DD)/(J_1 + b J_D),   J_X = ∫dc1 dc2 de Θ(−c12·e)|c12·e| f̃ f̃ X,
/// so a measured ⟨D⟩_coll determines b directly, independently of the cooling rate.
struct ContactIntegrals {
  Estimate one, dyad, dyad_squared;  ///< J_1, J_D, J_DD at the given a2
  [[nodiscard]] Estimate mean_dyad(double b) const;
  [[nodiscard]] Estimate b_from_mean_dyad(double mean_dyad, double mean_dyad_error) const;
};

ContactIntegrals contact_integrals(int dimension, double a2, double dyad_factor,
                                   const QuadratureOptions& options = {});

/// The Gauss–Hermite order that makes the centre-of-mass sum exact for moment p (a2 and b terms).
int exact_hermite_order(int p);

}  // namespace molchaos::theory
