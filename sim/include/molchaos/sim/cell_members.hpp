// The members of each cell of the engine's grid, as one singly linked list per cell: a 4-byte
// head per cell here, and a 4-byte link per particle kept where the scan reads next (Links): in
// the particle's own record when the pair search reads the members' records at once (the link
// then shares their cache lines and costs no miss of its own), or in an array of its own. A
// stencil's scan reads its cells' heads, which lie in runs of three consecutive cells (12 bytes);
// blocks of slots per cell would read 32 bytes a cell, most of them empty in a dilute gas, and need
// room for the most crowded cell. For 10^5 spheres at packing 0.1 (2.5 cells a sphere) the heads
// take 1 MB against 8 MB of blocks, and the scans' cache misses were half of the engine's
// (callgrind). Which particle lies in which cell is the engine's business; this class only files
// them. Links: anything whose [i] is particle i's link (std::int32_t&), for i = 0 .. n, the
// last one the end's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "molchaos/sim/huge_pages.hpp"

namespace molchaos::sim {

/// Links kept in records with a member `std::int32_t next` (one more record than particles).
template <class Record>
struct RecordLinks {
  Record* records;
  std::int32_t& operator[](std::int32_t i) const { return records[i].next; }
};

class CellMembers {
 public:
  /// `cells` empty cells for particles 0 .. n-1, linked by `links`.
  template <class Links>
  void reset(std::size_t cells, std::int32_t n, Links&& links) {
    end_ = n;
    head_.assign(cells, n);
    links[n] = n;  // the end links to itself (gather())
  }

  /// Files i in cell c, first of its members.
  template <class Links>
  void add(Links&& links, std::int32_t i, int c) {
    links[i] = head_[c];
    head_[c] = i;
  }
  /// Takes i out of cell c, which holds it (a walk over the members before it: a few at most).
  template <class Links>
  void remove(Links&& links, std::int32_t i, int c) {
    std::int32_t* link = &head_[c];
    while (*link != i) link = &links[*link];
    *link = links[i];
  }

  /// The members of the Count given cells, written to out, which has room for every particle
  /// and one more; returns their number. The first Unrolled members of a cell are copied without
  /// a branch (the end links to itself, and a copy of it is overwritten by the next member):
  /// whether a cell holds one member more is a coin flip for the branch predictor. Only members
  /// beyond those take the loop.
  template <int Count, int Unrolled = 1, class Links>
  [[gnu::always_inline]] std::int32_t gather(const Links& links, const int* cells,
                                             std::int32_t* out) const {
    std::int32_t k = 0;
    // Members lie below the end (n): j < end rather than j != end, which x86 adds as the carry of
    // one compare (cmp, adc) instead of setting a byte and widening it (4 instructions a copy);
    // a local copy of the end, which the stores to out do not make the compiler read again.
    const auto end = static_cast<std::uint32_t>(end_);
#pragma GCC unroll 27
    for (int s = 0; s < Count; ++s) {
      std::int32_t j = head_[cells[s]];
#pragma GCC unroll 8
      for (int u = 0; u < Unrolled; ++u) {
        out[k] = j;
        k += static_cast<std::uint32_t>(j) < end;
        j = links[j];
      }
      for (; static_cast<std::uint32_t>(j) != end; j = links[j]) out[k++] = j;
    }
    return k;
  }

  /// The walk over a cell's members: the first, then the links until end().
  std::int32_t first(int c) const { return head_[c]; }
  std::int32_t end() const { return end_; }
  /// Sized for `cells` cells and n particles (a restored checkpoint's check).
  bool shaped_for(std::size_t cells, std::int32_t n) const {
    return end_ == n && head_.size() == cells;
  }

  /// Every member, for checkpoints (checkpoint.hpp); the links are their holder's. Self:
  /// const CellMembers to write, CellMembers to read.
  template <class Self, class Archive>
  static void checkpoint_members(Self& self, Archive& archive) {
    archive(self.end_, self.head_);
  }

  /// The bytes of the heads of `cells` cells.
  static std::size_t memory_bytes_for(std::size_t cells) { return cells * sizeof(std::int32_t); }
  std::size_t memory_bytes() const { return head_.capacity() * sizeof(std::int32_t); }

 private:
  std::int32_t end_ = 0;  // the link that ends a list: the particle count
  HugePageVector<std::int32_t> head_;
};

}  // namespace molchaos::sim
