// Structure factors and coarse-grained fields of a snapshot (see the header).
#include "molchaos/validation/structure_factor.hpp"

#include <array>
#include <cmath>
#include <complex>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

namespace molchaos::validation {
namespace {

void check(const sim::Snapshot& s, int d) {
  if (d != 2 && d != 3)
    throw std::invalid_argument("dimension: value " + std::to_string(d) +
                                " is not allowed; allowed values 2 or 3");
  if (s.positions.empty() || s.positions.size() != s.velocities.size() ||
      s.positions.size() % static_cast<std::size_t>(d) != 0 || !(s.box > 0))
    throw std::invalid_argument("snapshot: positions and velocities must hold d·N numbers");
}

double snapshot_temperature(const sim::Snapshot& s) {
  double sum = 0;
  for (double v : s.velocities) sum += v * v;
  return sum / static_cast<double>(s.velocities.size());  // Σv²/(N d)
}

/// Lattice vectors m of the half space (first nonzero component positive), |m|² ≤ max_norm2.
std::map<int, std::vector<std::array<int, 3>>> half_space_shells(int d, int max_norm2) {
  std::map<int, std::vector<std::array<int, 3>>> shells;
  const int r = static_cast<int>(std::floor(std::sqrt(static_cast<double>(max_norm2))));
  const int rz = d == 3 ? r : 0;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      for (int z = -rz; z <= rz; ++z) {
        const int n2 = x * x + y * y + z * z;
        if (n2 == 0 || n2 > max_norm2) continue;
        const bool upper = x > 0 || (x == 0 && (y > 0 || (y == 0 && z > 0)));
        if (upper) shells[n2].push_back({x, y, z});
      }
  return shells;
}

}  // namespace

std::vector<StructureShell> structure_factors(const sim::Snapshot& s, int d, int max_norm2) {
  check(s, d);
  const std::size_t n = s.positions.size() / static_cast<std::size_t>(d);
  const double count = static_cast<double>(n);
  const double T = snapshot_temperature(s);
  const double unit = 2.0 * std::numbers::pi / s.box;
  std::vector<StructureShell> out;
  for (const auto& [norm2, vectors] : half_space_shells(d, max_norm2)) {
    StructureShell shell;
    shell.lattice_norm2 = norm2;
    shell.wavenumber = unit * std::sqrt(static_cast<double>(norm2));
    shell.wavevectors = static_cast<int>(vectors.size());
    for (const auto& m : vectors) {
      double k[3] = {unit * m[0], unit * m[1], unit * m[2]};
      std::complex<double> rho = 0, j[3] = {0, 0, 0};
      for (std::size_t i = 0; i < n; ++i) {
        double phase = 0;
        for (int a = 0; a < d; ++a) phase += k[a] * s.positions[d * i + a];
        const std::complex<double> e{std::cos(phase), std::sin(phase)};
        rho += e;
        for (int a = 0; a < d; ++a) j[a] += s.velocities[d * i + a] * e;
      }
      std::complex<double> j_long = 0;
      for (int a = 0; a < d; ++a) j_long += j[a] * (k[a] / shell.wavenumber);
      double j2 = 0;
      for (int a = 0; a < d; ++a) j2 += std::norm(j[a]);
      shell.density += std::norm(rho) / count;
      shell.longitudinal += std::norm(j_long) / (count * T);
      shell.transverse += (j2 - std::norm(j_long)) / (count * T * (d - 1));
    }
    shell.density /= shell.wavevectors;
    shell.longitudinal /= shell.wavevectors;
    shell.transverse /= shell.wavevectors;
    out.push_back(shell);
  }
  return out;
}

CoarseField coarse_grain(const sim::Snapshot& s, int d, int cells) {
  check(s, d);
  if (cells < 1) throw std::invalid_argument("cells: must be at least 1");
  const std::size_t n = s.positions.size() / static_cast<std::size_t>(d);
  CoarseField f;
  f.dimension = d;
  f.cells = cells;
  f.cell_width = s.box / cells;
  std::size_t total = 1;
  for (int a = 0; a < d; ++a) total *= static_cast<std::size_t>(cells);
  f.number.assign(total, 0.0);
  f.velocity.assign(total * d, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t index = 0, stride = 1;
    for (int a = 0; a < d; ++a) {
      int c = static_cast<int>(s.positions[d * i + a] / f.cell_width);
      c = std::min(std::max(c, 0), cells - 1);
      index += static_cast<std::size_t>(c) * stride;
      stride *= static_cast<std::size_t>(cells);
    }
    f.number[index] += 1.0;
    for (int a = 0; a < d; ++a) f.velocity[d * index + a] += s.velocities[d * i + a];
  }
  f.temperature = snapshot_temperature(s);
  double flow = 0;
  for (std::size_t c = 0; c < total; ++c) {
    if (f.number[c] == 0) continue;
    ++f.occupied_cells;
    for (int a = 0; a < d; ++a) {
      f.velocity[d * c + a] /= f.number[c];
      flow += f.number[c] * f.velocity[d * c + a] * f.velocity[d * c + a];
    }
  }
  f.flow_temperature = flow / (static_cast<double>(n) * d);
  return f;
}

std::vector<double> vorticity(const CoarseField& f) {
  if (f.dimension != 2) throw std::invalid_argument("vorticity: defined here for d = 2 only");
  const int m = f.cells;
  std::vector<double> w(static_cast<std::size_t>(m) * m);
  auto u = [&](int x, int y, int a) {
    x = (x + m) % m;
    y = (y + m) % m;
    return f.velocity[2 * (static_cast<std::size_t>(y) * m + x) + a];
  };
  for (int y = 0; y < m; ++y)
    for (int x = 0; x < m; ++x)
      w[static_cast<std::size_t>(y) * m + x] =
          ((u(x + 1, y, 1) - u(x - 1, y, 1)) - (u(x, y + 1, 0) - u(x, y - 1, 0))) /
          (2.0 * f.cell_width);
  return w;
}

}  // namespace molchaos::validation
