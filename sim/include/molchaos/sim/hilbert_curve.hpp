// The position of a grid point along a Hilbert curve in d dimensions, for numbering particles so
// that neighbours in space are neighbours in memory. J. Skilling, "Programming the Hilbert curve",
// AIP Conf. Proc. 707, 381 (2004): the coordinates are transformed in place into the "transposed"
// Hilbert index, whose bits, interleaved, give the index. Consecutive indices are neighbouring
// points (one step along one axis), which a row-by-row order lacks at the end of every row.
#pragma once

#include <cstdint>

namespace molchaos::sim {

/// Hilbert index of the point x (D coordinates, each below 2^bits; D * bits <= 64).
template <int D>
std::uint64_t hilbert_index(const int* x, int bits) {
  std::uint32_t u[D];
  for (int a = 0; a < D; ++a) u[a] = static_cast<std::uint32_t>(x[a]);
  const std::uint32_t top = std::uint32_t{1} << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {  // inverse undo
    const std::uint32_t p = q - 1;
    for (int a = 0; a < D; ++a) {
      if (u[a] & q) {
        u[0] ^= p;  // invert the low bits of the first axis
      } else {      // exchange the low bits of the first axis and axis a
        const std::uint32_t t = (u[0] ^ u[a]) & p;
        u[0] ^= t;
        u[a] ^= t;
      }
    }
  }
  for (int a = 1; a < D; ++a) u[a] ^= u[a - 1];  // Gray encode
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (u[D - 1] & q) t ^= q - 1;
  for (int a = 0; a < D; ++a) u[a] ^= t;
  std::uint64_t h = 0;  // interleave: the top bit of axis 0 first
  for (int b = bits - 1; b >= 0; --b)
    for (int a = 0; a < D; ++a) h = (h << 1) | ((u[a] >> b) & 1u);
  return h;
}

/// Bits per axis that hold coordinates 0 .. side - 1 (at least 1).
inline int hilbert_bits(int side) {
  int bits = 1;
  while ((1 << bits) < side) ++bits;
  return bits;
}

}  // namespace molchaos::sim
