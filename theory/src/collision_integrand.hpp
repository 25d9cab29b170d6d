// The integrand of the collision moments and contact averages at one relative velocity, summed
// exactly over the centre-of-mass velocity: the piece both quadratures (fixed Gauss rules and
// adaptive GSL) share. Internal to molchaos::theory.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "molchaos/theory/gauss_rules.hpp"

namespace molchaos::theory::detail {

/// The terms a2^i a3^j b^k of the product [1 + a2 S2 + a3 S3]₁ [1 + a2 S2 + a3 S3]₂ [1 + b D]:
/// the integrand is exactly this polynomial in (a2, a3, b), so these terms are the whole expansion.
struct TermPowers {
  const char* name;
  int a2, a3, b;
};
inline constexpr std::size_t k_term_count = 12;
inline constexpr std::array<TermPowers, k_term_count> k_terms{{{"1", 0, 0, 0},
                                                               {"a2", 1, 0, 0},
                                                               {"a2^2", 2, 0, 0},
                                                               {"b", 0, 0, 1},
                                                               {"a2*b", 1, 0, 1},
                                                               {"a2^2*b", 2, 0, 1},
                                                               {"a3", 0, 1, 0},
                                                               {"a2*a3", 1, 1, 0},
                                                               {"a3^2", 0, 2, 0},
                                                               {"a3*b", 0, 1, 1},
                                                               {"a2*a3*b", 1, 1, 1},
                                                               {"a3^2*b", 0, 2, 1}}};
/// The first six terms involve a2 and b only.
inline constexpr std::size_t k_a2_term_count = 6;

/// What multiplies the weighted pair distribution: Δ(c1^p + c2^p) for μ_p, or a contact
/// observable averaged over colliding pairs.
enum class Observable {
  moment_change,         ///< Δ(c1^p + c2^p) in a collision with restitution ε
  one,                   ///< 1 (collision frequency)
  normal_product,        ///< (c1·e)(c2·e)
  velocity_product,      ///< c1·c2
  dyad,                  ///< D = κ(c1·e)(c2·e) − c1·c2
  normal_speed_squared,  ///< (c12·e)²
};

struct IntegrandSpec {
  int dimension = 2;
  int moment = 2;
  Observable observable = Observable::moment_change;
  double restitution = 1.0;
  double dyad_factor = 3.0;
  bool with_a3 = false;  ///< whether the S3 terms are needed (raises the polynomial degree)
};

/// Total polynomial degree in (C, g) of the integrand without its Gaussian factor.
int polynomial_degree(const IntegrandSpec& spec);

using TermSums = std::array<double, k_term_count>;

/// Σ_C w_C W_T(c1, c2) X(c1, c2) over a tensor Gauss–Hermite rule in the centre-of-mass velocity C
/// (weight e^{−2C²}), with e = x̂ and g = (−u, ρ, 0); exact for the polynomial when the order is.
class CentreOfMassSum {
 public:
  CentreOfMassSum(const IntegrandSpec& spec, int hermite_order);

  /// sums[T] += scale · Σ_C …, and magnitudes[T] += |scale| · Σ_C |…| (for the rounding bound).
  void accumulate(double u, double rho, double scale, TermSums& sums, TermSums& magnitudes) const;

  [[nodiscard]] const IntegrandSpec& spec() const { return spec_; }

 private:
  IntegrandSpec spec_;
  std::vector<std::array<double, 3>> nodes_;
  std::vector<double> weights_;
};

}  // namespace molchaos::theory::detail
