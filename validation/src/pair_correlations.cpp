// Pair correlation functions by a cell list over one snapshot, and their ensemble estimates.
#include "molchaos/validation/pair_correlations.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace molchaos::validation {

const char* to_string(PairSide side) {
  switch (side) {
    case PairSide::approaching:
      return "approaching";
    case PairSide::receding:
      return "receding";
    default:
      return "all";
  }
}

std::vector<double> pair_grid(double r_max, int near, double near_width, int far) {
  if (near < 0 || far < 0 || near + far < 1 || !(near_width > 0.0))
    throw std::invalid_argument("pair_grid: need at least one bin and a positive near_width");
  std::vector<double> edges{1.0};
  for (int k = 1; k <= near; ++k) edges.push_back(1.0 + k * near_width);
  const double start = edges.back();
  if (!(r_max > start)) throw std::invalid_argument("pair_grid: r_max must exceed the near bins");
  for (int k = 1; k < far; ++k) edges.push_back(start * std::pow(r_max / start, double(k) / far));
  // The last edge r_max itself: start (r_max/start)^1 can round a unit in the last place above
  // it, beyond the half box that pair_sums() allows (the run's snapshots then went unmeasured).
  if (far > 0) edges.push_back(r_max);
  return edges;
}

std::vector<double> default_pair_grid(double box) { return pair_grid(0.5 * box, 10, 0.05, 16); }

namespace {

double shell_volume(int d, double lo, double hi) {
  return d == 2 ? std::numbers::pi * (hi * hi - lo * lo)
                : 4.0 / 3.0 * std::numbers::pi * (hi * hi * hi - lo * lo * lo);
}

// Adds pair (i, j) to its bin. c = v/√(2T) makes ⟨c·c⟩ = d/2 per particle.
template <int D>
void add_pair(const sim::Snapshot& s, std::size_t i, std::size_t j, double scale2,
              const std::vector<double>& edges, std::vector<PairBinSums>& bins) {
  double r[D], r2 = 0.0;
  const double half = 0.5 * s.box;
  for (int a = 0; a < D; ++a) {
    double x = s.positions[D * i + a] - s.positions[D * j + a];
    if (x > half) x -= s.box;
    if (x < -half) x += s.box;
    r[a] = x;
    r2 += x * x;
  }
  if (r2 < edges.front() * edges.front() || r2 >= edges.back() * edges.back()) return;
  const double dist = std::sqrt(r2);
  const auto k = static_cast<std::size_t>(std::upper_bound(edges.begin(), edges.end(), dist) -
                                          edges.begin() - 1);
  double v1r = 0.0, v2r = 0.0, v12 = 0.0, approach = 0.0;
  for (int a = 0; a < D; ++a) {
    const double v1 = s.velocities[D * i + a], v2 = s.velocities[D * j + a];
    v1r += v1 * r[a];
    v2r += v2 * r[a];
    v12 += v1 * v2;
    approach += (v1 - v2) * r[a];
  }
  const double par = v1r * v2r / r2 * scale2;
  const double perp = (v12 * scale2 - par) / (D - 1);
  PairBinSums& b = bins[k];
  for (int side : {0, approach < 0.0 ? 1 : 2}) {
    b.pairs[side] += 1.0;
    b.sum_par[side] += par;
    b.sum_perp[side] += perp;
    b.sum_par2[side] += par * par;
    b.sum_perp2[side] += perp * perp;
  }
}

template <int D>
void collect(const sim::Snapshot& s, double scale2, const std::vector<double>& edges,
             std::vector<PairBinSums>& bins) {
  const std::size_t n = s.positions.size() / D;
  const int m = static_cast<int>(std::floor(s.box / edges.back()));
  if (m < 3) {  // cells would neighbour themselves: all pairs
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) add_pair<D>(s, i, j, scale2, edges, bins);
    return;
  }
  // Cell list: cells of side ≥ r_max, each pair found once from the 3^D stencil with i < j.
  const std::size_t cells = D == 2 ? std::size_t(m) * m : std::size_t(m) * m * m;
  std::vector<std::vector<std::size_t>> members(cells);
  auto coord = [&](std::size_t i, int a) {
    return std::min(m - 1, static_cast<int>(s.positions[D * i + a] / s.box * m));
  };
  auto index = [&](const int* c) {
    std::size_t k = 0;
    for (int a = D - 1; a >= 0; --a) k = k * m + static_cast<std::size_t>((c[a] + m) % m);
    return k;
  };
  for (std::size_t i = 0; i < n; ++i) {
    int c[D];
    for (int a = 0; a < D; ++a) c[a] = coord(i, a);
    members[index(c)].push_back(i);
  }
  const int stencil = D == 2 ? 9 : 27;
  for (std::size_t i = 0; i < n; ++i) {
    int c[D];
    for (int a = 0; a < D; ++a) c[a] = coord(i, a);
    for (int k = 0; k < stencil; ++k) {
      int nb[D];
      int rest = k;
      for (int a = 0; a < D; ++a) {
        nb[a] = c[a] + rest % 3 - 1;
        rest /= 3;
      }
      for (std::size_t j : members[index(nb)])
        if (j > i) add_pair<D>(s, i, j, scale2, edges, bins);
    }
  }
}

}  // namespace

SnapshotPairSums pair_sums(const sim::Snapshot& snap, int dimension,
                           const std::vector<double>& edges) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: value " + std::to_string(dimension) +
                                " is outside the allowed set {2, 3}");
  if (edges.size() < 2 || edges.back() > 0.5 * snap.box)
    throw std::invalid_argument("edges: need two or more, the largest at most half the box");
  const std::size_t n = snap.positions.size() / static_cast<std::size_t>(dimension);
  SnapshotPairSums out;
  out.edges = edges;
  out.bins.assign(edges.size() - 1, {});
  double v2 = 0.0;
  for (double v : snap.velocities) v2 += v * v;
  out.temperature = v2 / static_cast<double>(n * dimension);
  const double scale2 = 1.0 / (2.0 * out.temperature);
  if (dimension == 2)
    collect<2>(snap, scale2, edges, out.bins);
  else
    collect<3>(snap, scale2, edges, out.bins);
  const double volume = std::pow(snap.box, dimension);
  const double all_pairs = 0.5 * static_cast<double>(n) * static_cast<double>(n - 1);
  out.all_pairs = all_pairs;
  for (std::size_t k = 0; k + 1 < edges.size(); ++k)
    out.uncorrelated_pairs.push_back(all_pairs * shell_volume(dimension, edges[k], edges[k + 1]) /
                                     volume);
  return out;
}

namespace {

// Ratio estimator Σy/Σx over independent snapshots with the standard error from their scatter.
Measurement ratio_estimate(const std::vector<double>& y, const std::vector<double>& x) {
  double sy = 0.0, sx = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    sy += y[i];
    sx += x[i];
  }
  Measurement m;
  if (sx <= 0.0) return m;
  m.value = sy / sx;
  const double k = static_cast<double>(y.size());
  if (k < 2) return m;
  double ss = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i)
    ss += (y[i] - m.value * x[i]) * (y[i] - m.value * x[i]);
  m.error = std::sqrt(k / (k - 1.0) * ss) / sx;
  return m;
}

// Mean of independent products from their sums: Σp/n ± √((Σp²/n − mean²)/n).
Measurement pair_mean(double n, double sum, double sum2) {
  if (n <= 0.0) return {};
  const double mean = sum / n;
  return {mean, n > 1.0 ? std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1.0)) : 0.0};
}

}  // namespace

std::vector<PairCorrelationBin> combine_pair_sums(const std::vector<SnapshotPairSums>& snapshots,
                                                  int /*dimension*/) {
  std::vector<PairCorrelationBin> out;
  if (snapshots.empty()) return out;
  const auto& edges = snapshots.front().edges;
  for (std::size_t k = 0; k + 1 < edges.size(); ++k)
    for (PairSide side : k_pair_sides) {
      const auto s = static_cast<std::size_t>(side);
      std::vector<double> pairs, par, perp, ideal;
      double par2 = 0.0, perp2 = 0.0, ideal_sum = 0.0, binomial_variance = 0.0;
      for (const auto& snap : snapshots) {
        const double count = snap.bins[k].pairs[s];
        pairs.push_back(count);
        if (snap.all_pairs > 0.0) binomial_variance += count * (1.0 - count / snap.all_pairs);
        par.push_back(snap.bins[k].sum_par[s]);
        perp.push_back(snap.bins[k].sum_perp[s]);
        ideal.push_back(snap.uncorrelated_pairs[k]);
        par2 += snap.bins[k].sum_par2[s];
        perp2 += snap.bins[k].sum_perp2[s];
        ideal_sum += snap.uncorrelated_pairs[k];
      }
      PairCorrelationBin b;
      b.r_lo = edges[k];
      b.r_hi = edges[k + 1];
      b.side = side;
      for (double p : pairs) b.pairs += p;
      b.g = {b.pairs / ideal_sum, std::sqrt(binomial_variance) / ideal_sum};
      b.g_snapshot_error = ratio_estimate(pairs, ideal).error;
      b.G_par = pair_mean(b.pairs, ratio_estimate(par, pairs).value * b.pairs, par2);
      b.G_perp = pair_mean(b.pairs, ratio_estimate(perp, pairs).value * b.pairs, perp2);
      b.G_par_snapshot_error = ratio_estimate(par, pairs).error;
      b.G_perp_snapshot_error = ratio_estimate(perp, pairs).error;
      out.push_back(b);
    }
  return out;
}

double chi_square_p_value(double chi2, int dof) {
  return dof > 0 ? gsl_cdf_chisq_Q(chi2, static_cast<double>(dof)) : 1.0;
}

double normal_score(double t, int dof) {
  if (dof <= 0) return 0.0;
  const double z = gsl_cdf_ugaussian_Qinv(gsl_cdf_tdist_Q(std::abs(t), static_cast<double>(dof)));
  return t < 0 ? -z : z;
}

double student_p_two_sided(double t, int dof) {
  return dof > 0 ? 2.0 * gsl_cdf_tdist_Q(std::abs(t), static_cast<double>(dof)) : 1.0;
}

ChiSquare chi_square_zero_velocity_correlations(const std::vector<PairCorrelationBin>& bins) {
  ChiSquare c;
  for (const auto& b : bins) {
    if (b.side != PairSide::all) continue;
    for (const Measurement& m : {b.G_par, b.G_perp})
      if (m.error > 0.0) {
        c.chi2 += (m.value / m.error) * (m.value / m.error);
        ++c.dof;
      }
  }
  c.p_value = chi_square_p_value(c.chi2, c.dof);
  return c;
}

}  // namespace molchaos::validation
