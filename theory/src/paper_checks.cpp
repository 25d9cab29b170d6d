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

std::vector<PaperCheck> prefactor_checks(int dimension, const QuadratureOptions& options) {
  require_dimension(dimension);
  std::vector<PaperCheck> rows;
  const double d = dimension;
  // μ2(0,0)/(1 − ε²): paper prints ½√(2π) (eq. mu2a2b, stated for disks). Computed by quadrature.
  const double eps = 0.5;
  const Estimate base = collision_moment(dimension, 2, eps, 0.0, 0.0, k_paper_dyad_factor, options);
  const double scale = 1.0 - eps * eps;
  const double paper_mu2 = 0.5 * std::sqrt(2.0 * std::numbers::pi);
  rows.push_back({"mu2(0,0)/(1-eps^2)", paper_mu2, base.value / scale, base.error / scale,
                  verdict(paper_mu2, base.value / scale, base.error / scale),
                  "quadrature of eq. defmu2 at a2 = b = 0"});
  // Prefactor of eq. tau0, 1/tau0 = c g2 sigma^{d-1} n sqrt(2 T0/m) mu2: derived c = 1/d.
  rows.push_back({"tau0 prefactor c in 1/tau0 = c g2 n sqrt(2T0) mu2", k_paper_tau0_prefactor,
                  1.0 / d, 0.0, verdict(k_paper_tau0_prefactor, 1.0 / d, 0.0),
                  "second moment of the Enskog-Boltzmann equation: c = 1/d"});
  // ω0 = c g2 σ^{d−1} n √(πT0/m): paper prints c = 1/3; derived c = √2 μ̂_d /(d √π).
  const double omega_c =
      std::sqrt(2.0) * mu2_maxwell_prefactor(dimension) / (d * std::sqrt(std::numbers::pi));
  rows.push_back({"omega0 prefactor c in omega0 = c g2 n sqrt(pi T0)", k_paper_omega0_prefactor,
                  omega_c, 0.0, verdict(k_paper_omega0_prefactor, omega_c, 0.0),
                  "c = 1/2 (d = 2), 2/3 (d = 3)"});
  // Temperature definition, eq. TDef: T = m/(c n) ∫ v² f; derived c = d.
  rows.push_back({"temperature definition c in T = m/(c n) int v^2 f", k_paper_temperature_divisor,
                  d, 0.0, verdict(k_paper_temperature_divisor, d, 0.0),
                  "equipartition in d dimensions: c = d"});
  return rows;
}

}  // namespace molchaos::theory
