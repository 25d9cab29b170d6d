// Storage of the neighbour lists of dense spheres (Smallenburg, arXiv 2201.01100): for each
// particle a block of `capacity` slots holding its neighbours (the particles whose shell centres
// lie within the list cutoff of its own), then room. Every list keeps one spare slot, which
// the engine's pair search may overwrite (it pads an odd list there). Which particles are
// neighbours is the engine's business (cells, shell centres); this class only files them.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "molchaos/sim/huge_pages.hpp"

namespace molchaos::sim {

class NeighbourLists {
 public:
  /// n empty lists of `capacity` slots (capacity kept from before when 0 is passed).
  void reset(std::int32_t n, int capacity) {
    n_ = n;
    if (capacity > 0) capacity_ = capacity;
    count_.assign(static_cast<std::size_t>(n), 0);
    assign_in_huge_pages(slots_, static_cast<std::size_t>(n) * capacity_, std::int32_t{-1});
  }

  int capacity() const { return capacity_; }
  std::int32_t count(std::int32_t i) const { return count_[i]; }
  /// i's capacity() slots: its count(i) neighbours, then room (at least one spare slot).
  std::int32_t* slots(std::int32_t i) {
    return slots_.data() + static_cast<std::size_t>(i) * capacity_;
  }
  const std::int32_t* slots(std::int32_t i) const {
    return slots_.data() + static_cast<std::size_t>(i) * capacity_;
  }
  std::span<const std::int32_t> neighbours(std::int32_t i) const {
    return {slots(i), static_cast<std::size_t>(count_[i])};
  }
  void prefetch(std::int32_t i) const {
    __builtin_prefetch(&count_[i]);
    __builtin_prefetch(slots(i));
    __builtin_prefetch(slots(i) + 16);
  }

  /// Appends j to i's list; doubles every list's capacity when i's would lose its spare slot.
  void add(std::int32_t i, std::int32_t j) {
    if (count_[i] + 1 >= capacity_) grow();
    slots(i)[count_[i]++] = j;
  }
  /// Removes j from i's list (the last entry takes its place).
  void remove(std::int32_t i, std::int32_t j) {
    std::int32_t* list = slots(i);
    for (std::int32_t k = 0; k < count_[i]; ++k)
      if (list[k] == j) {
        list[k] = list[--count_[i]];
        return;
      }
  }
  /// Empties i's list.
  void clear(std::int32_t i) { count_[i] = 0; }

  /// Every member, for checkpoints (checkpoint.hpp). Self: const NeighbourLists to write,
  /// NeighbourLists to read.
  template <class Self, class Archive>
  static void checkpoint_members(Self& self, Archive& archive) {
    archive(self.n_, self.capacity_, self.slots_, self.count_);
  }

  std::size_t memory_bytes() const {
    return slots_.capacity() * sizeof(std::int32_t) + count_.capacity() * sizeof(std::int32_t);
  }

 private:
  void grow() {
    const int old = capacity_;
    capacity_ = std::max(8, 2 * old);
    std::vector<std::int32_t> grown;
    assign_in_huge_pages(grown, static_cast<std::size_t>(n_) * capacity_, std::int32_t{-1});
    for (std::int32_t i = 0; i < n_; ++i)
      for (std::int32_t k = 0; k < count_[i]; ++k)
        grown[static_cast<std::size_t>(i) * capacity_ + k] =
            slots_[static_cast<std::size_t>(i) * old + k];
    slots_.swap(grown);
  }

  std::int32_t n_ = 0;
  int capacity_ = 0;
  std::vector<std::int32_t> slots_, count_;
};

}  // namespace molchaos::sim
