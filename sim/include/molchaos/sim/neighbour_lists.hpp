// Storage of the neighbour lists of dense spheres (Smallenburg, arXiv 2201.01100): for each
// particle a block of whole cache lines holding its count, then its neighbours (the particles
// whose shell centres lie within the list cutoff of its own), then room. A prediction reads the
// count and the first 15 neighbours from one line, where a separate array of counts and blocks
// at any offset cost two or three. Every list keeps one spare slot, which the engine's pair
// search may overwrite (it pads an odd list there). Which particles are neighbours is the
// engine's business (cells, shell centres); this class only files them.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "molchaos/sim/huge_pages.hpp"

namespace molchaos::sim {

class NeighbourLists {
 public:
  /// n empty lists of at least `capacity` slots (capacity kept from before when 0 is passed).
  void reset(std::int32_t n, int capacity) {
    n_ = n;
    if (capacity > 0) lines_ = (capacity + 1 + k_line_slots - 1) / k_line_slots;  // + the count
    lines_of_lists_.assign(static_cast<std::size_t>(n) * lines_, Line{});
  }

  /// Slots of a list: its neighbours and the room after them (0 before the first reset).
  int capacity() const { return lines_ == 0 ? 0 : lines_ * k_line_slots - 1; }
  std::int32_t count(std::int32_t i) const { return block(i)[0]; }
  /// i's capacity() slots: its count(i) neighbours, then room (at least one spare slot).
  std::int32_t* slots(std::int32_t i) { return block(i) + 1; }
  const std::int32_t* slots(std::int32_t i) const { return block(i) + 1; }
  std::span<const std::int32_t> neighbours(std::int32_t i) const {
    return {slots(i), static_cast<std::size_t>(count(i))};
  }
  /// The lines with i's count and first 31 neighbours.
  void prefetch(std::int32_t i) const {
    __builtin_prefetch(block(i));
    __builtin_prefetch(block(i) + k_line_slots);
  }

  /// Appends j to i's list; doubles every list's capacity when i's would lose its spare slot.
  void add(std::int32_t i, std::int32_t j) {
    if (count(i) + 2 >= lines_ * k_line_slots) grow();  // count + 1 >= capacity()
    std::int32_t* b = block(i);
    b[1 + b[0]++] = j;
  }
  /// Removes j from i's list (the last entry takes its place).
  void remove(std::int32_t i, std::int32_t j) {
    std::int32_t* b = block(i);
    std::int32_t k = 1;
#if defined(__SSE2__)
    // The first line's 15 members compared at once: no loop whose end the branch predictor would
    // have to guess (a shell exit strikes its particle out of each old neighbour's list).
    const __m128i key = _mm_set1_epi32(j);
    int found = 0;
    for (int q = 0; q < 4; ++q) {
      const __m128i four = _mm_load_si128(reinterpret_cast<const __m128i*>(b) + q);
      found |= _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(four, key))) << (4 * q);
    }
    // Members only: slot 0 holds the count, slots after the count hold stale entries.
    const int members = b[0] < k_line_slots - 1 ? b[0] : k_line_slots - 1;  // of the first line
    found &= ((2 << members) - 1) & ~1;
    if (found != 0) {
      k = __builtin_ctz(static_cast<unsigned>(found));
      b[k] = b[b[0]--];
      return;
    }
    k = k_line_slots;  // not among the first line's: on with the rest
#endif
    for (; k <= b[0]; ++k)
      if (b[k] == j) {
        b[k] = b[b[0]--];
        return;
      }
  }
  /// Empties i's list.
  void clear(std::int32_t i) { block(i)[0] = 0; }

  /// Whether these are n lists, each with its spare slot and only members in [0, n) (a
  /// restored checkpoint's, before the engine reads them).
  bool well_formed(std::int32_t n) const {
    if (n != n_ || lines_ < 1 || lines_ > k_max_lines ||
        lines_of_lists_.size() != static_cast<std::size_t>(n) * static_cast<std::size_t>(lines_))
      return false;
    for (std::int32_t i = 0; i < n; ++i) {
      if (count(i) < 0 || count(i) >= capacity()) return false;  // and the spare slot
      for (const std::int32_t j : neighbours(i))
        if (j < 0 || j >= n) return false;
    }
    return true;
  }

  /// Every member, for checkpoints (checkpoint.hpp). Self: const NeighbourLists to write,
  /// NeighbourLists to read.
  template <class Self, class Archive>
  static void checkpoint_members(Self& self, Archive& archive) {
    archive(self.n_, self.lines_, self.lines_of_lists_);
  }

  std::size_t memory_bytes() const { return lines_of_lists_.capacity() * sizeof(Line); }

 private:
  static constexpr int k_line_slots = 16;
  static constexpr int k_max_lines = 1 << 20;  // a restored number beyond it is refused
  struct alignas(64) Line {
    std::int32_t slot[k_line_slots] = {};
  };
  static_assert(sizeof(Line) == 64);

  std::int32_t* block(std::int32_t i) {
    return lines_of_lists_[static_cast<std::size_t>(i) * lines_].slot;
  }
  const std::int32_t* block(std::int32_t i) const {
    return lines_of_lists_[static_cast<std::size_t>(i) * lines_].slot;
  }

  void grow() {
    const int old = lines_;
    lines_ = 2 * old;
    HugePageVector<Line> grown;
    grown.assign(static_cast<std::size_t>(n_) * lines_, Line{});
    for (std::size_t i = 0; i < static_cast<std::size_t>(n_); ++i)
      std::copy_n(&lines_of_lists_[i * old], old, &grown[i * lines_]);
    lines_of_lists_.swap(grown);
  }

  std::int32_t n_ = 0;
  int lines_ = 0;  // per list (0 before the first reset)
  HugePageVector<Line> lines_of_lists_;
};

}  // namespace molchaos::sim
