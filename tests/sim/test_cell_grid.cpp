// Unit tests of the cell grid's index arithmetic: numbering, stencils and the slabs entered on a
// cell crossing, checked against their definitions on small periodic grids.
#define BOOST_TEST_MODULE sim_cell_grid
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <set>

#include "molchaos/sim/cell_grid.hpp"

using namespace molchaos::sim;

namespace {

template <int D>
std::set<int> stencil_set(const int* x, int cps) {
  int cells[stencil_size<D>()];
  neighbour_cells<D>(x, cps, cells);
  return std::set<int>(cells, cells + stencil_size<D>());
}

// Periodic distance along one axis between cell coordinates.
int axis_distance(int a, int b, int cps) {
  const int d = std::abs(a - b);
  return std::min(d, cps - d);
}

template <int D>
void check_grid(int cps) {
  int count = 1;
  for (int a = 0; a < D; ++a) count *= cps;
  for (int c = 0; c < count; ++c) {
    int x[D];
    cell_coords<D>(c, cps, x);
    BOOST_TEST(cell_index<D>(x, cps) == c);  // numbering and coordinates are inverse
    int fast[D];
    CellCoordinates<D>{cps}(c, fast);
    BOOST_TEST(std::equal(x, x + D, fast));  // the division-free coordinates agree
    // The stencil: 3^D distinct cells, exactly those within one cell along every axis.
    const std::set<int> stencil = stencil_set<D>(x, cps);
    BOOST_TEST(stencil.size() == static_cast<std::size_t>(stencil_size<D>()));
    for (int other = 0; other < count; ++other) {
      int y[D];
      cell_coords<D>(other, cps, y);
      bool near = true;
      for (int a = 0; a < D; ++a) near = near && axis_distance(x[a], y[a], cps) <= 1;
      BOOST_TEST(near == (stencil.count(other) == 1));
    }
    // The slab entered when moving from cell x into its neighbour along axis, direction dir:
    // the new stencil minus the old one.
    for (int axis = 0; axis < D; ++axis)
      for (int dir : {-1, 1}) {
        int to[D];
        for (int a = 0; a < D; ++a) to[a] = x[a];
        to[axis] = wrap(x[axis] + dir, cps);
        std::set<int> expected;
        for (int cell : stencil_set<D>(to, cps))
          if (stencil.count(cell) == 0) expected.insert(cell);
        int slab[stencil_size<D>()];
        const int size = slab_cells<D>(to, cps, axis, dir, slab);
        BOOST_TEST(size == slab_size<D>());
        BOOST_TEST((std::set<int>(slab, slab + size) == expected));
      }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(wrap_is_periodic_for_one_step) {
  BOOST_TEST(wrap(-1, 5) == 4);
  BOOST_TEST(wrap(5, 5) == 0);
  BOOST_TEST(wrap(3, 5) == 3);
}

BOOST_AUTO_TEST_CASE(disks_grid_stencils_and_slabs) {
  for (int cps : {4, 5, 7}) check_grid<2>(cps);
}

BOOST_AUTO_TEST_CASE(spheres_grid_stencils_and_slabs) {
  for (int cps : {4, 5}) check_grid<3>(cps);
}

// The division-free coordinates on the largest grids the engine can make (indices near 2^31).
BOOST_AUTO_TEST_CASE(division_free_coordinates_on_large_grids) {
  for (int cps : {46340, 46341 - 1000, 1290, 1291}) {
    const long long count2 = static_cast<long long>(cps) * cps;
    for (long long c : {0LL, 1LL, cps - 1LL, cps + 0LL, count2 / 2, count2 - 1}) {
      int x[2], fast[2];
      cell_coords<2>(static_cast<int>(c), cps, x);
      CellCoordinates<2>{cps}(static_cast<int>(c), fast);
      BOOST_TEST(std::equal(x, x + 2, fast));
    }
    if (static_cast<long long>(cps) * cps * cps < (1LL << 31)) {
      const long long count3 = static_cast<long long>(cps) * cps * cps;
      long long differing = 0;
      for (long long c = count3 - 1; c >= 0; c -= 997) {
        int x[3], fast[3];
        cell_coords<3>(static_cast<int>(c), cps, x);
        CellCoordinates<3>{cps}(static_cast<int>(c), fast);
        differing += !std::equal(x, x + 3, fast);
      }
      BOOST_TEST(differing == 0);
    }
  }
}
