// The event calendar: one pending event per particle, O(1) insert, move and pop on average.
// A calendar queue (Brown 1988; as used by Smallenburg, arXiv 2201.01100): time is cut into
// buckets of width `bucket_width`; the buckets of the current cycle [cycle_start, cycle_start +
// buckets) hold doubly linked lists of particles, later events wait in an overflow list that is
// re-filed when a new cycle starts. Events due in the current bucket or earlier are linked into
// the current bucket, whose list is scanned for the earliest event; a bitmap of occupied buckets
// leads to the next non-empty bucket without a walk over the empty ones. The bucket width is chosen
// so that a bucket holds about one event, so the scan is short whatever N (a scan is cheaper
// than keeping the current bucket in a heap: measured, instruction counts).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "molchaos/sim/huge_pages.hpp"

namespace molchaos::sim {

class EventCalendar {
 public:
  /// Empties the calendar for particles 0..n-1; times are measured from `origin`.
  void reset(std::int32_t n, double origin, double bucket_width, std::int64_t buckets) {
    n_ = n;
    origin_ = origin;
    width_ = bucket_width;
    inv_width_ = 1.0 / bucket_width;
    buckets_ = 64;
    while (buckets_ < buckets) buckets_ *= 2;
    mask_ = buckets_ - 1;
    e_.assign(static_cast<std::size_t>(n), Entry{});
    head_.assign(static_cast<std::size_t>(buckets_), std::int32_t{-1});
    occupied_.assign(static_cast<std::size_t>(buckets_ / 64), 0);
    overflow_ = -1;
    current_ = 0;
    cycle_start_ = 0;
    filed_ = 0;
  }

  double time(std::int32_t i) const { return e_[i].time; }
  double bucket_width() const { return width_; }

  /// Schedules particle i's event at t (replacing its previous one); t may be +inf.
  void update(std::int32_t i, double t) {
    remove(i);
    e_[i].time = t;
    insert(i);
  }

  /// The earliest event: (time, particle); time is +inf when no event is finite. Among events at
  /// the same time, the first in the current bucket's list (deterministic).
  std::pair<double, std::int32_t> top() {
    for (;;) {
      std::int32_t k = head_[static_cast<std::size_t>(current_ & mask_)];
      if (k >= 0) {
        std::int32_t best = k;
        double t = e_[k].time;
        for (k = e_[k].next; k >= 0; k = e_[k].next)
          if (e_[k].time < t) {
            t = e_[k].time;
            best = k;
          }
        return {t, best};
      }
      if (filed_ == 0) {
        if (!jump_to_overflow()) return {k_inf, 0};
        continue;
      }
      // On to the next occupied bucket. The filed events lie in buckets [current_, cycle_start_ +
      // buckets_), whose slots follow the current slot cyclically, so the cyclically next set bit
      // is the earliest of them (and the cycle does not end before it). Events are filed, so a
      // search over the whole bitmap finds one.
      const std::int64_t slot = current_ & mask_;
      current_ += (next_occupied(slot, buckets_ / 64) - slot) & mask_;
    }
  }

  /// A guess of the event after top()'s particle `first` (for prefetching its data): another event
  /// of the current bucket, else the first of the next occupied bucket nearby; -1 if none found.
  std::int32_t guess_next(std::int32_t first) const {
    const std::int64_t slot = current_ & mask_;
    const std::int32_t k = head_[static_cast<std::size_t>(slot)];
    if (k != first) return k;
    if (e_[k].next >= 0) return e_[k].next;
    const std::int64_t next = next_occupied((slot + 1) & mask_, 1);  // nearby: one word further
    return next < 0 ? -1 : head_[static_cast<std::size_t>(next)];
  }

  void prefetch(std::int32_t i) const { __builtin_prefetch(&e_[static_cast<std::size_t>(i)]); }

  /// Whether this is a calendar of particles 0..n-1 that top() pops in time order (a restored
  /// checkpoint's, before the engine runs it): every particle filed once, in the bucket its time
  /// belongs to (the current one if its time has passed) or, beyond the cycle, in the overflow
  /// list; lists linked both ways and the bitmap marking exactly the non-empty buckets.
  bool well_formed(std::int32_t n) const {
    if (n != n_ || e_.size() != static_cast<std::size_t>(n) || buckets_ < 64 ||
        buckets_ > (std::int64_t{1} << 40) || (buckets_ & (buckets_ - 1)) != 0 ||
        mask_ != buckets_ - 1 || head_.size() != static_cast<std::size_t>(buckets_) ||
        occupied_.size() != static_cast<std::size_t>(buckets_ / 64) || !(width_ > 0) ||
        !std::isfinite(width_) || inv_width_ != 1.0 / width_ || !std::isfinite(origin_) ||
        current_ < cycle_start_ || cycle_start_ < 0)
      return false;
    std::vector<char> seen(static_cast<std::size_t>(n), 0);
    std::int64_t filed = 0;
    // Walks the list from `head`, whose members must all be `where`; false if it is broken.
    auto list_holds = [&](std::int32_t head, std::int32_t where) {
      std::int32_t prev = -1;
      for (std::int32_t k = head; k != -1; prev = k, k = e_[k].next) {
        if (k < 0 || k >= n || seen[k] || e_[k].where != where || e_[k].prev != prev) return false;
        seen[k] = 1;
        const std::int64_t b = bucket_of(e_[k].time);
        const bool in_cycle = b < cycle_start_ + buckets_;
        if (where == k_in_overflow ? in_cycle
                                   : !in_cycle || (std::max(b, current_) & mask_) != where)
          return false;
        filed += where != k_in_overflow;
      }
      return true;
    };
    for (std::int64_t s = 0; s < buckets_; ++s) {
      const std::int32_t head = head_[static_cast<std::size_t>(s)];
      const bool marked = (occupied_[static_cast<std::size_t>(s >> 6)] >> (s & 63)) & 1;
      if (marked != (head != -1) || !list_holds(head, static_cast<std::int32_t>(s))) return false;
    }
    if (!list_holds(overflow_, k_in_overflow) || filed != filed_) return false;
    return std::find(seen.begin(), seen.end(), 0) == seen.end();
  }

  /// Every member, for checkpoints (checkpoint.hpp): a restored calendar pops the same events in
  /// the same order, ties included. Self: const EventCalendar to write, EventCalendar to read.
  template <class Self, class Archive>
  static void checkpoint_members(Self& self, Archive& archive) {
    archive(self.n_, self.origin_, self.width_, self.inv_width_, self.buckets_, self.mask_,
            self.current_, self.cycle_start_, self.filed_, self.e_, self.head_, self.occupied_,
            self.overflow_);
  }

  /// The memory_bytes() of a calendar reset for n particles with 4 n buckets (the engine's).
  static std::size_t memory_bytes_for(std::int32_t n) {
    std::size_t buckets = 64;
    while (buckets < 4 * static_cast<std::size_t>(n)) buckets *= 2;
    return static_cast<std::size_t>(n) * sizeof(Entry) + buckets * sizeof(std::int32_t) +
           buckets / 64 * sizeof(std::uint64_t);
  }

  std::size_t memory_bytes() const {
    return e_.capacity() * sizeof(Entry) + head_.capacity() * sizeof(std::int32_t) +
           occupied_.capacity() * sizeof(std::uint64_t);
  }

 private:
  static constexpr double k_inf = std::numeric_limits<double>::infinity();
  static constexpr std::int32_t k_absent = -2, k_in_overflow = -1;

  // Absolute bucket number of time t (saturating for far or infinite times). Truncation instead of
  // floor (no SSE4.1 round on baseline x86-64, floor is a long sequence): the two differ only
  // for t < origin_, where both give a bucket <= current_ (the current bucket), as they must.
  std::int64_t bucket_of(double t) const {
    const double b = (t - origin_) * inv_width_;
    if (!(b < 4e18)) return std::numeric_limits<std::int64_t>::max();
    return static_cast<std::int64_t>(b);
  }

  // The first occupied bucket slot at or cyclically after `slot`, reading at most `more_words`
  // bitmap words beyond slot's own; -1 if none of those bits is set. top() and guess_next() share
  // it: top() searches the whole bitmap, guess_next() only nearby.
  std::int64_t next_occupied(std::int64_t slot, std::int64_t more_words) const {
    std::int64_t w = slot >> 6;
    std::uint64_t bits = occupied_[static_cast<std::size_t>(w)] & (~std::uint64_t{0} << (slot & 63));
    for (std::int64_t read = 0; bits == 0; ++read) {
      if (read == more_words) return -1;
      w = (w + 1) & (buckets_ / 64 - 1);
      bits = occupied_[static_cast<std::size_t>(w)];
    }
    return w * 64 + __builtin_ctzll(bits);
  }

  void insert(std::int32_t i) {
    const std::int64_t b = bucket_of(e_[i].time);
    if (b < cycle_start_ + buckets_) {
      const std::int64_t slot = std::max(b, current_) & mask_;
      link(i, static_cast<std::int32_t>(slot), head_[static_cast<std::size_t>(slot)]);
      occupied_[static_cast<std::size_t>(slot) >> 6] |= std::uint64_t{1} << (slot & 63);
      ++filed_;
    } else {
      link(i, k_in_overflow, overflow_);
    }
  }

  void remove(std::int32_t i) {
    const std::int32_t w = e_[i].where;
    if (w == k_absent) return;
    const std::int32_t p = e_[i].prev, q = e_[i].next;
    if (p >= 0) {
      e_[p].next = q;
    } else if (w == k_in_overflow) {
      overflow_ = q;
    } else {
      head_[static_cast<std::size_t>(w)] = q;
      if (q < 0) occupied_[static_cast<std::size_t>(w) >> 6] &= ~(std::uint64_t{1} << (w & 63));
    }
    if (q >= 0) e_[q].prev = p;
    if (w != k_in_overflow) --filed_;
    e_[i].where = k_absent;
  }

  void link(std::int32_t i, std::int32_t where, std::int32_t& head) {
    e_[i].where = where;
    e_[i].prev = -1;
    e_[i].next = head;
    if (head >= 0) e_[head].prev = i;
    head = i;
  }

  // A new cycle of buckets starts at current_: re-file the overflow events that now fit.
  void new_cycle() {
    cycle_start_ = current_;
    std::int32_t i = overflow_;
    overflow_ = -1;
    while (i >= 0) {
      const std::int32_t following = e_[i].next;
      insert(i);
      i = following;
    }
  }

  // Nothing filed in the buckets: restart the cycle at the earliest overflow event.
  bool jump_to_overflow() {
    double earliest = k_inf;
    for (std::int32_t i = overflow_; i >= 0; i = e_[i].next)
      earliest = std::min(earliest, e_[i].time);
    if (!(earliest < k_inf)) return false;
    const std::int64_t b = bucket_of(earliest);
    if (b > (std::int64_t{1} << 60)) {  // far beyond the bucket range: restart the clock there
      origin_ = earliest;
      current_ = 0;
    } else {
      current_ = std::max(current_, b);
    }
    new_cycle();
    return true;
  }

  std::int32_t n_ = 0;
  double origin_ = 0, width_ = 1, inv_width_ = 1;
  std::int64_t buckets_ = 1, mask_ = 0, current_ = 0, cycle_start_ = 0;
  std::int64_t filed_ = 0;  // events in the buckets (not in the overflow)
  // Everything the calendar keeps per particle, in one 24-byte record (one cache miss per event).
  struct Entry {
    double time = k_inf;
    std::int32_t where = k_absent;      // bucket slot, or k_in_overflow / k_absent
    std::int32_t next = -1, prev = -1;  // in the bucket's or the overflow's list
  };
  HugePageVector<Entry> e_;
  HugePageVector<std::int32_t> head_;
  std::vector<std::uint64_t> occupied_;  // bit s set: bucket slot s holds events
  std::int32_t overflow_ = -1;
};

}  // namespace molchaos::sim
