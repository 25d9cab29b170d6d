// The paper's printed formulas and coefficients, each set beside what this suite computes.
// A printed number is a claim: every row carries the paper's value, the computed value with its
// error, and a verdict; the suite always uses its own value.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/paper_constants.hpp"

namespace molchaos::theory {

struct PaperCheck {
  std::string quantity;         ///< what is compared, e.g. "mu2 coefficient of b"
  std::optional<double> paper;  ///< printed value; empty where the paper prints none
  double computed = 0.0;
  double error = 0.0;              ///< error estimate of `computed`
  std::optional<bool> reproduced;  ///< empty where the paper prints no value
  std::string note;
};

/// Verdict: reproduced when the computed value agrees with the printed one by agreement()
/// (agreement.hpp: within 3 errors, or to 1e-12 for exact closed forms with zero error).
std::optional<bool> verdict(std::optional<double> paper, double computed, double error);

/// The coefficient rows of μ2/μ2(0,0) ("a2", "a2^2", "b", "a2*b", "a2^2*b") against the paper.
std::vector<PaperCheck> coefficient_checks(const ExpansionTable& table);

/// Prefactors of the paper's Eqs. (21), (22) and (24) (ω0) against the derivation in
/// cooling.hpp, for dimension d (the paper simulates d = 2). In d = 3 the rows built on Eq.
/// (21) (μ2(0,0) and ω0), derived with the 2D Sonine polynomial, carry no verdict and the
/// note "not applicable (the paper's formula is for d = 2 …)".
std::vector<PaperCheck> prefactor_checks(int dimension, const QuadratureOptions& options);

}  // namespace molchaos::theory
