// Unit tests of the Hilbert index: on grids of 2^bits points per side it numbers every point once
// (a bijection onto 0 .. 2^(d bits) - 1), and consecutive indices are neighbouring points.
#define BOOST_TEST_MODULE sim_hilbert_curve
#include <boost/test/unit_test.hpp>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "molchaos/sim/hilbert_curve.hpp"

using namespace molchaos::sim;

namespace {

template <int D>
void check_curve(int bits) {
  const int side = 1 << bits;
  std::int64_t count = 1;
  for (int a = 0; a < D; ++a) count *= side;
  std::vector<std::int64_t> point_of(static_cast<std::size_t>(count), -1);  // index -> point
  for (std::int64_t p = 0; p < count; ++p) {
    int x[D];
    std::int64_t rest = p;
    for (int a = 0; a < D; ++a, rest /= side) x[a] = static_cast<int>(rest % side);
    const std::uint64_t h = hilbert_index<D>(x, bits);
    BOOST_REQUIRE(h < static_cast<std::uint64_t>(count));
    BOOST_REQUIRE(point_of[h] == -1);  // no index given twice
    point_of[h] = p;
  }
  int far_steps = 0;
  for (std::int64_t h = 1; h < count; ++h) {
    int steps = 0;
    std::int64_t p = point_of[h - 1], q = point_of[h];
    for (int a = 0; a < D; ++a, p /= side, q /= side) steps += std::abs(int(p % side - q % side));
    far_steps += steps != 1;
  }
  BOOST_TEST(far_steps == 0);
}

}  // namespace

BOOST_AUTO_TEST_CASE(two_dimensional_curve_is_a_path_through_every_point) {
  for (int bits = 1; bits <= 6; ++bits) check_curve<2>(bits);
}

BOOST_AUTO_TEST_CASE(three_dimensional_curve_is_a_path_through_every_point) {
  for (int bits = 1; bits <= 4; ++bits) check_curve<3>(bits);
}

BOOST_AUTO_TEST_CASE(bits_cover_the_side) {
  BOOST_TEST(hilbert_bits(1) == 1);
  BOOST_TEST(hilbert_bits(2) == 1);
  BOOST_TEST(hilbert_bits(3) == 2);
  BOOST_TEST(hilbert_bits(1414) == 11);
}
