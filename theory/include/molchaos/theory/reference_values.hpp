// Closed forms of the μ2 expansion coefficients (derived in doc/theory.md and symbolically by
// theory/derivations/collision_moments.py at build time, read from its generated header). Used
// only to measure the error the quadrature reaches (tests, work–precision benchmark); the suite's
// results always come from the quadrature.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/exact_values.hpp"

namespace molchaos::theory::reference {

/// μ2(0,0)/(1 − ε²): √(2π)/2 (d = 2), √(2π) (d = 3).
inline double mu2_maxwell(int dimension) {
  return (dimension == 2 ? 0.5 : 1.0) * std::sqrt(2.0 * std::numbers::pi);
}

/// Coefficients of μ2/μ2(0,0) with the printed dyad 3·ee − U (ε-independent), from the
/// symbolic derivation.
inline std::vector<std::pair<std::string, double>> mu2_coefficients(int dimension) {
  std::vector<std::pair<std::string, double>> out;
  for (const char* name : {"a2", "a2^2", "b", "a2*b", "a2^2*b"}) {
    const exact::MomentTerm* t = exact::find_moment_term(dimension, 2, 3.0, name);
    out.emplace_back(name, exact::coefficient(*t, 0.5));
  }
  return out;
}

/// How far a μ2 table (printed dyad) is from the closed forms: the largest deviation of
/// μ2(0,0)/(1 − ε²) (relative) and of the five coefficients, and the largest error estimate.
struct TableError {
  double reached = 0.0;
  double estimated = 0.0;
};

inline TableError table_error(const ExpansionTable& table) {
  const double mu_hat = mu2_maxwell(table.dimension);
  const double scale = 1.0 - table.restitution * table.restitution;
  TableError e{std::abs(table.base.value / scale - mu_hat) / mu_hat, table.base.relative_error()};
  for (const auto& [name, value] : mu2_coefficients(table.dimension)) {
    const auto& c = table.term(name).coefficient;
    e.reached = std::max(e.reached, std::abs(c.value - value));
    e.estimated = std::max(e.estimated, c.error);
  }
  return e;
}

}  // namespace molchaos::theory::reference
