// The impact-parameter distribution of the colliding pairs: fractions per bin over runs, the
// flatness test of the pooled counts, and the study's claims on it.
#include "molchaos/validation/impact_parameter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "molchaos/validation/analysis.hpp"
#include "molchaos/validation/ensemble.hpp"
#include "molchaos/validation/pair_correlations.hpp"
#include "molchaos/validation/verdict.hpp"

namespace molchaos::validation {

std::vector<ImpactParameterRow> summarize_impact_parameter(int dimension, double density,
                                                           double restitution,
                                                           const std::string& mode,
                                                           const std::vector<RunContacts>& runs) {
  const std::size_t bins = sim::ContactMoments::k_impact_bins;
  std::vector<std::vector<double>> fractions(bins);
  std::vector<std::uint64_t> pooled(bins, 0);
  double inverse_collisions = 0.0;  // Σ_runs 1/collisions: the multinomial variance's run sum
  for (const auto& r : runs) {
    std::uint64_t total = 0;
    for (auto c : r.impact_histogram) total += c;
    if (!r.ok || total == 0) continue;
    inverse_collisions += 1.0 / static_cast<double>(total);
    for (std::size_t b = 0; b < bins; ++b) {
      fractions[b].push_back(static_cast<double>(r.impact_histogram[b]) /
                             static_cast<double>(total));
      pooled[b] += r.impact_histogram[b];
    }
  }
  const int n_runs = static_cast<int>(fractions[0].size());
  if (n_runs == 0) return {};
  const FlatnessTest flat = impact_flatness(pooled);
  const double p = 1.0 / static_cast<double>(bins);
  // Variance of the mean over runs of independent multinomial fractions: p(1 − p)/N_r / R².
  const double multinomial = p * (1.0 - p) * inverse_collisions / (double(n_runs) * n_runs);
  std::vector<ImpactParameterRow> rows;
  for (std::size_t b = 0; b < bins; ++b) {
    ImpactParameterRow row;
    row.dimension = dimension;
    row.density = density;
    row.restitution = restitution;
    row.mode = mode;
    row.runs = n_runs;
    row.s_lo = static_cast<double>(b) * p;
    row.s_hi = static_cast<double>(b + 1) * p;
    row.fraction = mean_and_standard_error(fractions[b]);
    row.scatter_over_multinomial = row.fraction.error * row.fraction.error / multinomial;
    row.flatness_chi2 = flat.chi2;
    row.flatness_dof = flat.dof;
    row.flatness_p = flat.p_value;
    rows.push_back(row);
  }
  return rows;
}

namespace {

// Flat at every point of one gas: the points' Pearson χ² summed (each point once: its first bin).
StudyClaim flatness_claim(const std::vector<ImpactParameterRow>& rows, const std::string& mode) {
  double chi2 = 0.0, scatter = 0.0;
  int dof = 0, bins = 0;
  for (const auto& r : rows) {
    if (r.mode != mode) continue;
    scatter += r.scatter_over_multinomial;
    ++bins;
    if (r.s_lo > 0.0) continue;
    chi2 += r.flatness_chi2;
    dof += r.flatness_dof;
  }
  const double p = chi_square_p_value(chi2, dof);
  return {fmt::format("{}: impact parameter uniform on [0, 1) at every point (molecular chaos)",
                      gas_name(mode)),
          p >= k_global_p_threshold ? "holds" : "fails", Measurement{chi2 / std::max(dof, 1), 0.0},
          fmt::format("chi2/dof of the pooled counts against flat over all bins and points, "
                      "chi2 = {:.1f}, dof = {}, p = {:.2g}; run scatter over multinomial "
                      "variance {:.2f} (mean over bins; 1 when the counts are multinomial)",
                      chi2, dof, p, scatter / std::max(bins, 1))};
}

// The grazing bin (s → 1): fraction·bins − 1, averaged over the points of one gas with equal
// weights (weights from standard errors of a few runs each would favour the points whose error
// came out small by chance).
StudyClaim grazing_claim(const std::vector<ImpactParameterRow>& rows, const std::string& mode) {
  double sum = 0.0, variance = 0.0;
  int points = 0;
  for (const auto& r : rows)
    if (r.mode == mode && r.s_hi >= 1.0) {
      const double bins = 1.0 / (r.s_hi - r.s_lo);
      sum += r.fraction.value * bins - 1.0;
      variance += std::pow(r.fraction.error * bins, 2);
      ++points;
    }
  const double n = std::max(points, 1);
  const Measurement m{sum / n, std::sqrt(variance) / n};
  const bool resolved = !agreement(m, {0.0, 0.0}).agrees;
  return {fmt::format("{}: excess of grazing collisions (last bin of s) over molecular chaos",
                      gas_name(mode)),
          resolved ? "resolved" : "not resolved", m,
          fmt::format("mean over the {} points of fraction/(1/bins) − 1 in the last bin: {} "
                      "grazing collisions than under molecular chaos",
                      points,
                      !resolved     ? "no more and no fewer"
                      : m.value < 0 ? "fewer"
                                    : "more")};
}

}  // namespace

std::vector<StudyClaim> impact_parameter_claims(const std::vector<ImpactParameterRow>& rows) {
  std::vector<StudyClaim> claims;
  for (const std::string mode : {"none", "flux", "dsmc"})
    if (std::any_of(rows.begin(), rows.end(), [&](const auto& r) { return r.mode == mode; })) {
      claims.push_back(flatness_claim(rows, mode));
      claims.push_back(grazing_claim(rows, mode));
    }
  return claims;
}

std::string impact_parameter_csv(const std::vector<ImpactParameterRow>& rows,
                                 const std::string& header) {
  std::string out = header;
  out +=
      "dimension,density,restitution,randomize,runs,bin_lo,bin_hi,fraction,fraction_err,"
      "scatter_over_multinomial,flatness_chi2,flatness_dof,flatness_p\n";
  for (const auto& r : rows)
    out += fmt::format("{},{},{},{},{},{:.3g},{:.3g},{:.8g},{:.3g},{:.3g},{:.4g},{},{:.3g}\n",
                       r.dimension, r.density, r.restitution, r.mode, r.runs, r.s_lo, r.s_hi,
                       r.fraction.value, r.fraction.error, r.scatter_over_multinomial,
                       r.flatness_chi2, r.flatness_dof, r.flatness_p);
  return out;
}

}  // namespace molchaos::validation
