// The engine's large arrays in transparent huge pages. Beyond the cache every event reads records
// of particles, cells and calendar at random, and with 4 KB pages most of those reads also miss
// the TLB. Where the kernel gives huge pages only on request (transparent_hugepage "madvise",
// Debian's default) an array of 1 MB or more asks for them before its pages are first touched;
// elsewhere the request is harmless (the kernel ignores it, or gives them anyway).
//
// Such an array starts on a 2 MB boundary and takes whole 2 MB pages: a huge page can only back
// an aligned 2 MB stretch, and an array placed anywhere by malloc held none below 4 MB and
// kept 4 KB pages at both ends above (at N = 10^5 spheres the events, the calendar and the cells,
// 8.6 MB read at random, held none). The rounding costs at most a page per array. Paired rates
// in doc/benchmarks.md.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace molchaos::sim {

template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr std::size_t k_huge_page = std::size_t{2} << 20;
  static constexpr std::size_t k_least_bytes = std::size_t{1} << 20;  // smaller: malloc's pages

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / 2 / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < k_least_bytes) return std::allocator<T>{}.allocate(n);
    const std::size_t held = (bytes + k_huge_page - 1) / k_huge_page * k_huge_page;
    void* p = ::operator new (held, std::align_val_t{k_huge_page});
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, held, MADV_HUGEPAGE);  // a hint: refused, the pages stay small
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < k_least_bytes)
      std::allocator<T>{}.deallocate(p, n);
    else
      ::operator delete (p, std::align_val_t{k_huge_page});
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
};

/// A std::vector whose storage of 1 MB or more lies in whole, aligned huge pages.
template <class T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace molchaos::sim
