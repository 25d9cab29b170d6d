// Paper-versus-suite rows for the kinetic theory.
#include "molchaos/theory/paper_checks.hpp"

#include <cmath>
#include <numbers>

#include "molchaos/theory/agreement.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/dimension.hpp"

namespace molchaos::theory {

std::optional<bool> verdict(std::optional<double> paper, double computed, double error) {
  if (!paper) return std::nullopt;
  return agreement({computed, error}, {*paper, 0.0}).agrees;
}

std::vector<PaperCheck> coefficient_checks(const ExpansionTable& table) {
  std::vector<PaperCheck> rows;
  for (const ExpansionTerm& t : table.terms) {
    std::optional<double> paper;
    if (table.moment == 2 && table.dyad_factor == k_paper_dyad_factor) {
      if (t.name == "a2") paper = k_paper_coefficient_a2;
      if (t.name == "b") paper = k_paper_coefficient_b;
    }
    PaperCheck row{"mu" + std::to_string(table.moment) + " coefficient of " + t.name,
                   paper,
                   t.coefficient.value,
                   t.coefficient.error,
                   verdict(paper, t.coefficient.value, t.coefficient.error),
                   ""};
    if (!paper) row.note = "not printed in the paper";
    rows.push_back(row);
  }
  return rows;
}

namespace {

// The exact rounding error of q = num/den (one division): the residual q·den − num is exact
// with a fused multiply-add, and q's error is that residual over den (0 where q is exact, 1/2).
double division_rounding(double num, double den) {
  const double q = num / den;
  return std::abs(std::fma(q, den, -num) / den);
}

// Eq. (21) and the ω0 of Eq. (24) built on it are the paper's integral for disks: its Sonine
// polynomial is the two-dimensional one (Eq. (19)) and ½√(2π) the d = 2 value of μ2(0,0)/(1 − ε²).
// In d = 3 they make no claim to test. Eq. (22) and Eq. (10) are written in d = 3 form (σ², 1/3)
// and are tested in either d.
constexpr const char* k_mu2_two_dimensional =
    "not applicable (the paper's formula is for d = 2: Eq. (21) with the 2D Sonine polynomial, "
    "Eq. (19))";
constexpr const char* k_omega0_two_dimensional =
    "not applicable (the paper's omega0, Eq. (24), is built on the d = 2 value of mu2(0,0) in Eq. "
    "(21))";

PaperCheck two_dimensional_row(int dimension, PaperCheck row, const char* why) {
  if (dimension != 2) {
    row.reproduced.reset();
    row.note = why;
  }
  return row;
}

}  // namespace

std::vector<PaperCheck> prefactor_checks(int dimension, const QuadratureOptions& options) {
  require_dimension(dimension);
  std::vector<PaperCheck> rows;
  const double d = dimension;
  // μ2(0,0)/(1 − ε²): paper prints ½√(2π) (Eq. (21), stated for disks). Computed by quadrature;
  // the division by 1 − ε² = 3/4 (exact) adds its rounding.
  const double eps = 0.5;
  const Estimate base = collision_moment(dimension, 2, eps, 0.0, 0.0, k_paper_dyad_factor, options);
  const double scale = 1.0 - eps * eps;
  const double paper_mu2 = 0.5 * std::sqrt(2.0 * std::numbers::pi);
  const double mu2_value = base.value / scale;
  const double mu2_error = base.error / scale + division_rounding(base.value, scale);
  rows.push_back(two_dimensional_row(
      dimension,
      {"mu2(0,0)/(1-eps^2)", paper_mu2, mu2_value, mu2_error,
       verdict(paper_mu2, mu2_value, mu2_error), "quadrature of Eq. (20) at a2 = b = 0"},
      k_mu2_two_dimensional));
  // Prefactor of Eq. (22), 1/tau0 = c g2 sigma^{d-1} n sqrt(2 T0/m) mu2: derived c = 1/d.
  const double tau0_c = 1.0 / d, tau0_error = division_rounding(1.0, d);
  rows.push_back({"tau0 prefactor c in 1/tau0 = c g2 n sqrt(2T0) mu2", k_paper_tau0_prefactor,
                  tau0_c, tau0_error, verdict(k_paper_tau0_prefactor, tau0_c, tau0_error),
                  "second moment of the Enskog-Boltzmann equation: c = 1/d"});
  // ω0 = c g2 σ^{d−1} n √(πT0/m): paper prints c = 1/3; derived c = √2 μ̂_d /(d √π). Rounding:
  // √2 (u), μ̂_d (π, the root: 2u), √π (2u), d·√π, the product and the quotient (3u): 8u.
  const double omega_c =
      std::sqrt(2.0) * mu2_maxwell_prefactor(dimension) / (d * std::sqrt(std::numbers::pi));
  const double omega_error = rounding_bound(omega_c, 8.0);
  rows.push_back(two_dimensional_row(
      dimension,
      {"omega0 prefactor c in omega0 = c g2 n sqrt(pi T0)", k_paper_omega0_prefactor, omega_c,
       omega_error, verdict(k_paper_omega0_prefactor, omega_c, omega_error),
       "c = 1/2 (d = 2), 2/3 (d = 3)"},
      k_omega0_two_dimensional));
  // Temperature definition, Eq. (10): T = m/(c n) ∫ v² f; derived c = d (an exact integer).
  rows.push_back({"temperature definition c in T = m/(c n) int v^2 f", k_paper_temperature_divisor,
                  d, 0.0, verdict(k_paper_temperature_divisor, d, 0.0),
                  "equipartition in d dimensions: c = d"});
  return rows;
}

}  // namespace molchaos::theory
