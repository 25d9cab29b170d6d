// The figure's long-wave fields (flow_field.hpp, long_wave_panel) against a field known exactly:
// particles on a square lattice (uniform density) carrying the shear wave v_y = a sin(2πx/L).
#define BOOST_TEST_MODULE validation_long_wave_panel
#include <boost/test/unit_test.hpp>
#include <cmath>

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
