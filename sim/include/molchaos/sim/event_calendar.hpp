// The event calendar: one pending event per particle, O(1) insert, move and pop on average.
// A calendar queue (Brown 1988; as used by Smallenburg, arXiv 2201.01100): time is cut into
// buckets of width `bucket_width`; the buckets of the current cycle [cycle_start, cycle_start +
// buckets) hold doubly linked lists of particles, later events wait in an overflow list that is
// re-filed when a new cycle starts, and the events of the current bucket sit in a small binary
// heap from which the earliest is taken. The bucket width is chosen so that a bucket holds about
// one event, so the heap stays tiny whatever N.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace molchaos::sim {

class EventCalendar {
 public:
  /// Empties the calendar for particles 0..n-1; times are measured from `origin`.
  void reset(std::int32_t n, double origin, double bucket_width, std::int64_t buckets) {
    n_ = n;
    origin_ = origin;
    width_ = bucket_width;
    inv_width_ = 1.0 / bucket_width;
    buckets_ = 1;
    while (buckets_ < buckets) buckets_ *= 2;
    mask_ = buckets_ - 1;
    e_.assign(static_cast<std::size_t>(n), Entry{});
    head_.assign(static_cast<std::size_t>(buckets_), -1);
    heap_.clear();
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

  /// The earliest event: (time, particle); time is +inf when no event is finite.
  std::pair<double, std::int32_t> top() {
    while (heap_.empty()) {
      if (filed_ == 0) {
        if (!jump_to_overflow()) return {k_inf, 0};
        continue;
      }
      ++current_;
      if (current_ == cycle_start_ + buckets_) new_cycle();
      load_bucket();
    }
    return {e_[heap_[0]].time, heap_[0]};
  }

  std::size_t memory_bytes() const {
    return e_.capacity() * sizeof(Entry) +
           (head_.capacity() + heap_.capacity()) * sizeof(std::int32_t);
  }

 private:
  static constexpr double k_inf = std::numeric_limits<double>::infinity();
  static constexpr std::int32_t k_absent = -3, k_in_heap = -2, k_in_overflow = -1;

  // Absolute bucket number of time t (saturating for far or infinite times).
  std::int64_t bucket_of(double t) const {
    const double b = std::floor((t - origin_) * inv_width_);
    if (!(b < 4e18)) return std::numeric_limits<std::int64_t>::max();
    return static_cast<std::int64_t>(b);
  }

  void insert(std::int32_t i) {
    const std::int64_t b = bucket_of(e_[i].time);
    if (b <= current_) {
      heap_push(i);
    } else if (b < cycle_start_ + buckets_) {
      link(i, static_cast<std::int32_t>(b & mask_), head_[static_cast<std::size_t>(b & mask_)]);
      ++filed_;
    } else {
      link(i, k_in_overflow, overflow_);
    }
  }

  void remove(std::int32_t i) {
    const std::int32_t w = e_[i].where;
    if (w == k_absent) return;
    if (w == k_in_heap) {
      heap_erase(i);
    } else {
      const std::int32_t p = e_[i].prev, q = e_[i].next;
      if (p >= 0)
        e_[p].next = q;
      else if (w == k_in_overflow)
        overflow_ = q;
      else
        head_[static_cast<std::size_t>(w)] = q;
      if (q >= 0) e_[q].prev = p;
      if (w != k_in_overflow) --filed_;
    }
    e_[i].where = k_absent;
  }

  void link(std::int32_t i, std::int32_t where, std::int32_t& head) {
    e_[i].where = where;
    e_[i].prev = -1;
    e_[i].next = head;
    if (head >= 0) e_[head].prev = i;
    head = i;
  }

  void load_bucket() {
    std::int32_t& head = head_[static_cast<std::size_t>(current_ & mask_)];
    for (std::int32_t i = head; i >= 0;) {
      const std::int32_t following = e_[i].next;
      --filed_;
      heap_push(i);
      i = following;
    }
    head = -1;
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
    load_bucket();
    return true;
  }

  void heap_push(std::int32_t i) {
    e_[i].where = k_in_heap;
    heap_.push_back(i);
    sift_up(static_cast<std::int32_t>(heap_.size()) - 1);
  }

  void heap_erase(std::int32_t i) {
    const std::int32_t p = e_[i].heap_pos;
    const std::int32_t last = heap_.back();
    heap_.pop_back();
    if (last == i) return;
    heap_[static_cast<std::size_t>(p)] = last;
    e_[last].heap_pos = p;
    sift_up(p);
    sift_down(e_[last].heap_pos);
  }

  void sift_up(std::int32_t p) {
    const std::int32_t i = heap_[static_cast<std::size_t>(p)];
    const double t = e_[i].time;
    while (p > 0) {
      const std::int32_t parent = (p - 1) / 2;
      const std::int32_t k = heap_[static_cast<std::size_t>(parent)];
      if (e_[k].time <= t) break;
      heap_[static_cast<std::size_t>(p)] = k;
      e_[k].heap_pos = p;
      p = parent;
    }
    heap_[static_cast<std::size_t>(p)] = i;
    e_[i].heap_pos = p;
  }

  void sift_down(std::int32_t p) {
    const std::int32_t size = static_cast<std::int32_t>(heap_.size());
    const std::int32_t i = heap_[static_cast<std::size_t>(p)];
    const double t = e_[i].time;
    for (;;) {
      std::int32_t child = 2 * p + 1;
      if (child >= size) break;
      if (child + 1 < size && e_[heap_[static_cast<std::size_t>(child) + 1]].time <
                                  e_[heap_[static_cast<std::size_t>(child)]].time)
        ++child;
      const std::int32_t k = heap_[static_cast<std::size_t>(child)];
      if (!(e_[k].time < t)) break;
      heap_[static_cast<std::size_t>(p)] = k;
      e_[k].heap_pos = p;
      p = child;
    }
    heap_[static_cast<std::size_t>(p)] = i;
    e_[i].heap_pos = p;
  }

  std::int32_t n_ = 0;
  double origin_ = 0, width_ = 1, inv_width_ = 1;
  std::int64_t buckets_ = 1, mask_ = 0, current_ = 0, cycle_start_ = 0;
  std::int64_t filed_ = 0;  // events in the buckets (not in heap or overflow)
  // Everything the calendar keeps per particle, in one 24-byte record (one cache miss per event).
  struct Entry {
    double time = k_inf;
    std::int32_t where = k_absent;      // bucket slot, or k_in_heap / k_in_overflow / k_absent
    std::int32_t next = -1, prev = -1;  // in the bucket's or the overflow's list
    std::int32_t heap_pos = -1;
  };
  std::vector<Entry> e_;
  std::vector<std::int32_t> head_, heap_;
  std::int32_t overflow_ = -1;
};

}  // namespace molchaos::sim
