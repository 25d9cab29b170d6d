// The figure's long-wave fields (flow_field.hpp, long_wave_panel) against a field known exactly:
// particles on a square lattice (uniform density) carrying the shear wave v_y = a sin(2πx/L);
// and their noise levels against the fields of gases without correlations.
#define BOOST_TEST_MODULE validation_long_wave_panel
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "molchaos/sim/result.hpp"
#include "molchaos/validation/flow_field.hpp"

using namespace molchaos;

BOOST_AUTO_TEST_CASE(shear_wave_is_reproduced_exactly) {
  constexpr int side = 40;  // particles per side
  constexpr double box = 200.0, a = 0.3;
  const double k = 2 * M_PI / box;
  sim::Snapshot s;
  s.box = box;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const double x = (i + 0.5) * box / side, y = (j + 0.5) * box / side;
      s.positions.insert(s.positions.end(), {x, y});
      s.velocities.insert(s.velocities.end(), {0.0, a * std::sin(k * x)});
    }
  constexpr int cells = 16;
  const auto p = validation::long_wave_panel(s, cells, 5, "test");
  BOOST_TEST_REQUIRE(p.vx.size() == static_cast<std::size_t>(cells * cells));
  // T = Σv²/(2N) = a²/4: fields are in units of √T = a/2, so u_y = 2 sin(kx), ω = 2k cos(kx).
  // The lattice sums of the wave are exact up to rounding: tolerance 1e-9.
  for (int y = 0; y < cells; ++y)
    for (int x = 0; x < cells; ++x) {
      const auto c = static_cast<std::size_t>(y * cells + x);
      const double px = (x + 0.5) * box / cells;
      BOOST_TEST(std::abs(p.vy[c] - 2 * std::sin(k * px)) < 1e-9);
      BOOST_TEST(std::abs(p.vx[c]) < 1e-9);
      BOOST_TEST(std::abs(p.vorticity[c] - 2 * k * std::cos(k * px)) < 1e-9);
      BOOST_TEST(std::abs(p.relative_density[c] - 1.0) < 1e-9);
    }
}

// A gas without correlations (uniform positions, Gaussian velocities independent of them): the
// fields' mean squares over the grid and over many such gases are the panel's noise levels
// squared, within 4 standard errors of that mean (each gas one sample).
BOOST_AUTO_TEST_CASE(noise_levels_are_those_of_a_gas_without_correlations) {
  constexpr int particles = 1000, gases = 200, cells = 24;
  constexpr double box = 150.0;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> where(0.0, box);
  std::normal_distribution<double> velocity;
  std::vector<double> density_ratio, vorticity_ratio;
  for (int g = 0; g < gases; ++g) {
    sim::Snapshot s;
    s.box = box;
    for (int i = 0; i < particles; ++i) {
      s.positions.insert(s.positions.end(), {where(rng), where(rng)});
      s.velocities.insert(s.velocities.end(), {velocity(rng), velocity(rng)});
    }
    const auto p = validation::long_wave_panel(s, cells, 5, "noise");
    double d2 = 0, w2 = 0;
    for (std::size_t c = 0; c < p.vorticity.size(); ++c) {
      d2 += (p.relative_density[c] - 1.0) * (p.relative_density[c] - 1.0);
      w2 += p.vorticity[c] * p.vorticity[c];
    }
    const auto points = static_cast<double>(p.vorticity.size());
    density_ratio.push_back(d2 / points / (p.density_noise * p.density_noise));
    vorticity_ratio.push_back(w2 / points / (p.vorticity_noise * p.vorticity_noise));
  }
  for (const auto* ratios : {&density_ratio, &vorticity_ratio}) {
    double sum = 0, sum2 = 0;
    for (double r : *ratios) {
      sum += r;
      sum2 += r * r;
    }
    const double mean = sum / gases;
    const double se = std::sqrt((sum2 / gases - mean * mean) / (gases - 1));
    BOOST_TEST_INFO("mean square / noise² = " << mean << " ± " << se);
    BOOST_TEST(std::abs(mean - 1.0) < 4.0 * se);
  }
}
