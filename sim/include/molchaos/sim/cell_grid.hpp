// The geometry of the cell grid: a periodic box cut into cells_per_side^d cubic cells, numbered
// x + cps (y + cps z); the 3^d stencil of a cell and the slab of 3^(d-1) cells that enters the
// stencil when a particle crosses into the next cell. Pure index arithmetic (no storage).
#pragma once

#include <cstdint>

namespace molchaos::sim {

template <int D>
constexpr int stencil_size() {
  return D == 2 ? 9 : 27;
}

template <int D>
constexpr int slab_size() {
  return D == 2 ? 3 : 9;
}

template <int D>
void cell_coords(int c, int cps, int* x) {
  for (int a = 0; a < D; ++a) {
    x[a] = c % cps;
    c /= cps;
  }
}

template <int D>
int cell_index(const int* x, int cps) {
  int c = 0;
  for (int a = D - 1; a >= 0; --a) c = c * cps + x[a];
  return c;
}

// cell_coords() without integer division (a few cycles instead of tens; the event loop needs a
// particle's cell coordinates at every event and keeps only its cell index): c / d as the high
// word of the 128-bit product c * m, m = floor(2^64 / d) + 1 (Granlund & Montgomery 1994). Exact
// for 0 <= c < 2^31 and d >= 1: c * m / 2^64 exceeds c / d by less than c / 2^64 < 2^-33, while
// c / d lies at least 1 / d > 2^-31 below the next integer. One multiply instead of the four
// conversions and products of a floating-point quotient.
namespace detail {
__extension__ typedef unsigned __int128 uint128;
inline std::uint64_t reciprocal(std::uint64_t d) { return ~std::uint64_t{0} / d + 1; }
inline int quotient(int c, std::uint64_t reciprocal) {
  return static_cast<int>((static_cast<uint128>(static_cast<std::uint64_t>(c)) * reciprocal) >> 64);
}
}  // namespace detail

template <int D>
struct CellCoordinates {
  int cps = 1;
  std::uint64_t per_row = 0;    // reciprocal of cps (0: cps = 1, every quotient 0)
  std::uint64_t per_layer = 0;  // reciprocal of cps^2

  explicit CellCoordinates(int cells_per_side = 1)
      : cps(cells_per_side),
        per_row(cells_per_side > 1 ? detail::reciprocal(static_cast<std::uint64_t>(cells_per_side))
                                   : 0),
        per_layer(cells_per_side > 1
                      ? detail::reciprocal(static_cast<std::uint64_t>(cells_per_side) *
                                           static_cast<std::uint64_t>(cells_per_side))
                      : 0) {}

  void operator()(int c, int* x) const {
    if constexpr (D == 3) {
      const int z = detail::quotient(c, per_layer);
      x[2] = z;
      c -= z * cps * cps;
    }
    const int y = detail::quotient(c, per_row);
    x[1] = y;
    x[0] = c - y * cps;
  }
};

inline int wrap(int x, int cps) { return x < 0 ? x + cps : (x >= cps ? x - cps : x); }

// The 3^D cells around c (periodic), c included.
template <int D>
void neighbour_cells(const int* x, int cps, int* out) {
  int k = 0;
  if constexpr (D == 2) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int y[2] = {wrap(x[0] + dx, cps), wrap(x[1] + dy, cps)};
        out[k++] = cell_index<2>(y, cps);
      }
  } else {
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int y[3] = {wrap(x[0] + dx, cps), wrap(x[1] + dy, cps), wrap(x[2] + dz, cps)};
          out[k++] = cell_index<3>(y, cps);
        }
  }
}

// The 3^(D-1) cells that enter the stencil when a particle moves into cell c along `axis` in
// direction `dir`: the layer at offset dir along axis.
template <int D>
int slab_cells(const int* coords, int cps, int axis, int dir, int* out) {
  int x[D];
  for (int a = 0; a < D; ++a) x[a] = coords[a];
  x[axis] = wrap(x[axis] + dir, cps);
  int k = 0;
  if constexpr (D == 2) {
    const int other = 1 - axis;
    for (int d = -1; d <= 1; ++d) {
      int y[2] = {x[0], x[1]};
      y[other] = wrap(x[other] + d, cps);
      out[k++] = cell_index<2>(y, cps);
    }
  } else {
    const int o1 = (axis + 1) % 3, o2 = (axis + 2) % 3;
    for (int d2 = -1; d2 <= 1; ++d2)
      for (int d1 = -1; d1 <= 1; ++d1) {
        int y[3] = {x[0], x[1], x[2]};
        y[o1] = wrap(x[o1] + d1, cps);
        y[o2] = wrap(x[o2] + d2, cps);
        out[k++] = cell_index<3>(y, cps);
      }
  }
  return k;
}

}  // namespace molchaos::sim
