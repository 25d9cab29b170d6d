// A reference for the engine's collision frequency under the shuffles at ε = 1: hard disks in a
// periodic box, every pair time (nine images) recomputed after every collision, so that no event
// bookkeeping (cells, calendar, stale events, one event per particle) stands between the rule and
// the count. O(N²) per collision: small N only. The protocol is `molchaos simulate`'s: a square
// lattice with Gaussian velocities, elastic relaxation without shuffle, T rescaled to 1 and the
// clock set to 0, then the run with the shuffle; collisions counted over (t_skip, t_end].
// Usage: reference_shuffle_frequency N DENSITY MODE SEED RELAX T_SKIP T_END
//   MODE 0: no shuffle. 1 and 2: the paper's shuffle, i, j take the velocities of two other
//   particles k, l drawn uniformly, assigned so that i, j separate. The paper does not say which
//   of k, l takes which post-collision velocity: 1 exchanges pairwise (the donor whose velocity
//   i takes gets v_i', as the engine does), 2 gives v_i' to k and v_j' to l in the order drawn.
// Prints ω/ω_E (Henderson's g2) and the collisions counted. doc/validation.md quotes its runs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace {

struct Gas {
  int n = 0;
  double box = 0;
  std::vector<double> x, y, vx, vy;

  // Time until i and j touch, +inf if they do not (the smaller root of |dr + dv t|² = 1).
  double pair_time(int i, int j) const {
    double dx0 = x[i] - x[j], dy0 = y[i] - y[j];
    dx0 -= box * std::round(dx0 / box);
    dy0 -= box * std::round(dy0 / box);
    const double dvx = vx[i] - vx[j], dvy = vy[i] - vy[j];
    const double v2 = dvx * dvx + dvy * dvy;
    double best = INFINITY;
    for (int a = -1; a <= 1; ++a)
      for (int c = -1; c <= 1; ++c) {
        const double dx = dx0 + a * box, dy = dy0 + c * box;
        const double b = dx * dvx + dy * dvy;
        if (b >= 0) continue;
        const double r2 = dx * dx + dy * dy;
        const double disc = b * b - v2 * (r2 - 1.0);
        if (disc < 0) continue;
        best = std::min(best, std::max(0.0, (r2 - 1.0) / (-b + std::sqrt(disc))));
      }
    return best;
  }

  // Zero momentum, T = <v²>/2 = 1.
  void rescale() {
    double px = 0, py = 0, sum = 0;
    for (int i = 0; i < n; ++i) px += vx[i], py += vy[i];
    for (int i = 0; i < n; ++i) {
      vx[i] -= px / n, vy[i] -= py / n;
      sum += vx[i] * vx[i] + vy[i] * vy[i];
    }
    const double f = 1.0 / std::sqrt(sum / (2.0 * n));
    for (int i = 0; i < n; ++i) vx[i] *= f, vy[i] *= f;
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 8) {
    std::fprintf(stderr, "usage: %s N DENSITY MODE(0|1|2) SEED RELAX T_SKIP T_END\n", argv[0]);
    return 2;
  }
  Gas gas;
  gas.n = std::atoi(argv[1]);
  const double density = std::atof(argv[2]);
  const int mode = std::atoi(argv[3]);
  std::mt19937_64 rng(std::strtoull(argv[4], nullptr, 10) * 1000003ULL + 17);
  const double relax = std::atof(argv[5]), t_skip = std::atof(argv[6]), t_end = std::atof(argv[7]);
  const int n = gas.n;
  gas.box = std::sqrt(n / density);
  gas.x.resize(n), gas.y.resize(n), gas.vx.resize(n), gas.vy.resize(n);
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  std::normal_distribution<double> normal;
  for (int i = 0; i < n; ++i) {
    gas.x[i] = (i % side + 0.5) * gas.box / side;
    gas.y[i] = (i / side + 0.5) * gas.box / side;
    gas.vx[i] = normal(rng);
    gas.vy[i] = normal(rng);
  }
  gas.rescale();
  std::uniform_int_distribution<int> uniform(0, n - 1);
  const long long relax_collisions = static_cast<long long>(relax * n / 2);
  bool relaxing = relax_collisions > 0;
  long long collisions = 0, counted = 0;
  double t = 0;
  for (;;) {
    double dt = INFINITY;
    int i = -1, j = -1;
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        if (const double s = gas.pair_time(a, b); s < dt) dt = s, i = a, j = b;
    if (!relaxing && t + dt > t_end) break;
    for (int k = 0; k < n; ++k) gas.x[k] += gas.vx[k] * dt, gas.y[k] += gas.vy[k] * dt;
    t += dt;
    double ex = gas.x[i] - gas.x[j], ey = gas.y[i] - gas.y[j];
    ex -= gas.box * std::round(ex / gas.box);
    ey -= gas.box * std::round(ey / gas.box);
    const double r = std::sqrt(ex * ex + ey * ey);
    ex /= r, ey /= r;
    const double gn = (gas.vx[i] - gas.vx[j]) * ex + (gas.vy[i] - gas.vy[j]) * ey;
    if (!(gn < 0)) continue;  // not approaching (rounding): no collision
    gas.vx[i] -= gn * ex, gas.vy[i] -= gn * ey, gas.vx[j] += gn * ex, gas.vy[j] += gn * ey;
    ++collisions;
    if (relaxing) {
      if (collisions >= relax_collisions) relaxing = false, gas.rescale(), t = 0;
      continue;
    }
    if (t > t_skip) ++counted;
    if (mode == 0) continue;
    int k, l;
    do k = uniform(rng);
    while (k == i || k == j);
    do l = uniform(rng);
    while (l == i || l == j || l == k);
    const bool swapped = (gas.vx[k] - gas.vx[l]) * ex + (gas.vy[k] - gas.vy[l]) * ey < 0;
    const int to_i = swapped ? l : k, to_j = swapped ? k : l;  // i, j then separate
    const double vix = gas.vx[i], viy = gas.vy[i], vjx = gas.vx[j], vjy = gas.vy[j];
    gas.vx[i] = gas.vx[to_i], gas.vy[i] = gas.vy[to_i], gas.vx[j] = gas.vx[to_j],
    gas.vy[j] = gas.vy[to_j];
    const int gets_vi = mode == 1 ? to_i : k, gets_vj = mode == 1 ? to_j : l;
    gas.vx[gets_vi] = vix, gas.vy[gets_vi] = viy, gas.vx[gets_vj] = vjx, gas.vy[gets_vj] = vjy;
  }
  const double eta = M_PI * density / 4, g2 = (1 - 7 * eta / 16) / ((1 - eta) * (1 - eta));
  const double omega_enskog = 2 * density * g2 * std::sqrt(M_PI);
  std::printf("%.8f %lld\n", 2.0 * counted / (n * (t_end - t_skip)) / omega_enskog, counted);
}
