// The initial state: positions by random sequential insertion or on a lattice, Maxwell velocities.
#include "molchaos/sim/initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "molchaos/sim/cell_grid.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/sim/parameters.hpp"

namespace molchaos::sim {

// Lattice with random vacancies and jitter. d = 2: k sites per row, an even number m of rows, odd
// rows shifted by half a spacing (a triangular lattice when the box allows it), the (k, m) with
// k m >= N that maximises the nearest-site distance; that reaches n = 1.1 (packing 0.86, above
// random close packing) for N = 1000. d = 3: a simple cubic lattice (n < ~1).
StartLattice start_lattice(int dimension, std::int64_t n, double box) {
  StartLattice lattice;
  if (dimension == 2) {
    const auto k_max = static_cast<std::int64_t>(std::floor(box));
    for (std::int64_t k = 1; k <= k_max; ++k) {
      std::int64_t m = (n + k - 1) / k;
      m += m % 2;  // even: the shifted rows must match across the periodic boundary
      const double a = box / static_cast<double>(k), h = box / static_cast<double>(m);
      const double d = std::min({a, std::sqrt(0.25 * a * a + h * h), 2.0 * h});
      if (d > lattice.nearest) lattice = {k, m, d};
    }
  } else {
    std::int64_t m = static_cast<std::int64_t>(std::ceil(std::cbrt(static_cast<double>(n)) - 1e-9));
    while (m * m * m < n) ++m;
    lattice = {m, m, box / static_cast<double>(m)};
  }
  return lattice;
}

double densest_start(int dimension, std::int64_t n, double box) {
  // fits() holds while nearest > 1 + 1e-9, and lattice distances scale with the box side: the
  // bound lies near density (nearest/(1 + 1e-9))^d at the density of `box`. The bound returned is
  // the check's own, the least density that fits() refuses with the box side as box_side()
  // computes it, found by bisection from that estimate (a bound computed apart from the check
  // differed from it in the sixth digit).
  const auto fits = [&](double density) {
    const double side = std::pow(static_cast<double>(n) / density, 1.0 / dimension);
    return start_lattice(dimension, n, side).fits();
  };
  const double density = static_cast<double>(n) / std::pow(box, dimension);
  const double estimate =
      density * std::pow(start_lattice(dimension, n, box).nearest / (1.0 + 1e-9), dimension);
  double lo = estimate, hi = estimate;
  for (double step = 1e-12; fits(hi) && step < 1.0; step *= 4.0) hi = estimate * (1.0 + step);
  for (double step = 1e-12; !fits(lo) && step < 1.0; step *= 4.0) lo = estimate * (1.0 - step);
  if (fits(hi) || !fits(lo)) return estimate;  // not bracketed: the estimate
  while (std::nextafter(lo, hi) < hi) {
    const double mid = lo + 0.5 * (hi - lo);
    if (mid <= lo || mid >= hi) break;
    (fits(mid) ? lo : hi) = mid;
  }
  return hi;
}

std::string too_dense_message(int dimension, std::int64_t n, double box) {
  const double density = static_cast<double>(n) / std::pow(box, dimension);
  return "density " + message_number(density) +
         " is too high to generate a non-overlapping initial state for N = " + std::to_string(n) +
         (dimension == 2 ? " disks (a staggered lattice with vacancies reaches n < "
                         : " spheres (a simple cubic lattice with vacancies reaches n < ") +
         message_number(densest_start(dimension, n, box)) + " for this N; close packing is " +
         message_number(close_packing_density(dimension)) + ")";
}

// Random sequential insertion on a grid of cells >= sigma while that is quick (low packing
// fraction); otherwise a simple lattice with random vacancies and jitter. Relaxation melts either.
template <int D>
std::vector<double> place_particles(std::int32_t n, double box, Rng& rng,
                                    const std::atomic<bool>* interrupt) {
  const double half_box = 0.5 * box;
  std::vector<double> positions(static_cast<std::size_t>(n) * D);
  const double packing = (D == 2 ? std::numbers::pi / 4.0 : std::numbers::pi / 6.0) *
                         static_cast<double>(n) / std::pow(box, D);
  const double rsa_limit = D == 2 ? 0.25 : 0.2;
  if (packing < rsa_limit) {
    // Cells of width >= 1, at most about 2 n of them: the grid must not scale with the box volume
    // (a dilute gas would need gigabytes). The cells only speed up the overlap test: any grid of
    // width >= 1 finds the same overlaps, so the positions do not depend on it.
    const double most_per_side = std::max(3.0, std::ceil(std::pow(2.0 * n, 1.0 / D)));
    const int g = static_cast<int>(std::floor(std::min(box, most_per_side)));  // >= 3
    const double w = box / g;
    std::size_t cells = 1;
    for (int a = 0; a < D; ++a) cells *= static_cast<std::size_t>(g);
    std::vector<std::int32_t> head(cells, -1), next(static_cast<std::size_t>(n), -1);
    constexpr int k_attempts = 100000;
    bool ok = true;
    for (std::int32_t i = 0; i < n && ok; ++i) {
      stop_build_if_interrupted(interrupt, i);
      int attempt = 0;
      for (; attempt < k_attempts; ++attempt) {
        double r[D];
        int x[D];
        for (int a = 0; a < D; ++a) {
          r[a] = rng.uniform() * box;
          x[a] = std::min(static_cast<int>(r[a] / w), g - 1);
        }
        int stencil[stencil_size<D>()];
        neighbour_cells<D>(x, g, stencil);
        bool free = true;
        for (int s = 0; s < stencil_size<D>() && free; ++s)
          for (std::int32_t j = head[stencil[s]]; j >= 0 && free; j = next[j]) {
            double d2 = 0;
            for (int a = 0; a < D; ++a) {
              double d = r[a] - positions[D * j + a];
              if (d > half_box) d -= box;
              if (d < -half_box) d += box;
              d2 += d * d;
            }
            if (d2 <= 1.0 + 1e-9) free = false;
          }
        if (!free) continue;
        for (int a = 0; a < D; ++a) positions[D * i + a] = r[a];
        const int c = cell_index<D>(x, g);
        next[i] = head[c];
        head[c] = i;
        break;
      }
      if (attempt == k_attempts) ok = false;
    }
    if (ok) return positions;
  }
  const StartLattice lattice = start_lattice(D, n, box);
  const std::int64_t per_row = lattice.per_row, rows = lattice.rows;
  const double nearest = lattice.nearest;
  if (!lattice.fits()) throw std::runtime_error(too_dense_message(D, n, box));
  const std::int64_t sites = D == 2 ? per_row * rows : per_row * per_row * per_row;
  std::vector<std::int64_t> site(static_cast<std::size_t>(sites));
  for (std::int64_t s = 0; s < sites; ++s) site[static_cast<std::size_t>(s)] = s;
  // Each coordinate moves by at most jitter/2, so a displacement is at most jitter sqrt(d)/2 and
  // two sites stay more than 1 apart.
  const double jitter = 0.99 * (nearest - 1.0) / std::sqrt(static_cast<double>(D));
  for (std::int32_t i = 0; i < n; ++i) {
    stop_build_if_interrupted(interrupt, i);
    const std::size_t pick =
        static_cast<std::size_t>(i) + static_cast<std::size_t>(rng.below(sites - i));
    std::swap(site[static_cast<std::size_t>(i)], site[pick]);
    const std::int64_t s = site[static_cast<std::size_t>(i)];
    double r[D];
    if constexpr (D == 2) {
      const std::int64_t column = s % per_row, row = s / per_row;
      const double a = box / static_cast<double>(per_row), h = box / static_cast<double>(rows);
      r[0] = (static_cast<double>(column) + (row % 2 == 0 ? 0.25 : 0.75)) * a;
      r[1] = (static_cast<double>(row) + 0.5) * h;
    } else {
      std::int64_t rest = s;
      for (int a = 0; a < D; ++a) {
        r[a] = (static_cast<double>(rest % per_row) + 0.5) * nearest;
        rest /= per_row;
      }
    }
    for (int a = 0; a < D; ++a) {
      double x = r[a] + (rng.uniform() - 0.5) * jitter;
      if (x < 0) x += box;
      if (x >= box) x -= box;
      positions[D * i + a] = x;
    }
  }
  return positions;
}

template <int D>
std::vector<double> maxwell_velocities(std::int32_t n, Rng& rng) {
  std::vector<double> v(static_cast<std::size_t>(n) * D);
  for (double& component : v) component = rng.normal();
  double mean[D] = {};
  for (std::int32_t i = 0; i < n; ++i)
    for (int a = 0; a < D; ++a) mean[a] += v[D * i + a];
  for (int a = 0; a < D; ++a) mean[a] /= n;
  double sum = 0;
  for (std::int32_t i = 0; i < n; ++i)
    for (int a = 0; a < D; ++a) {
      v[D * i + a] -= mean[a];
      sum += v[D * i + a] * v[D * i + a];
    }
  const double factor = std::sqrt(static_cast<double>(n) * D / sum);
  for (double& component : v) component *= factor;
  return v;
}

template std::vector<double> place_particles<2>(std::int32_t, double, Rng&,
                                                const std::atomic<bool>*);
template std::vector<double> place_particles<3>(std::int32_t, double, Rng&,
                                                const std::atomic<bool>*);
template std::vector<double> maxwell_velocities<2>(std::int32_t, Rng&);
template std::vector<double> maxwell_velocities<3>(std::int32_t, Rng&);

}  // namespace molchaos::sim
