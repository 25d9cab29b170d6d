// The engine's large arrays in transparent huge pages. Beyond the cache every event reads records
// of particles, cells and calendar at random, and with 4 KB pages most of those reads also miss
// the TLB. Where the kernel gives huge pages only on request (transparent_hugepage "madvise",
// Debian's default) the array asks for them before its pages are first touched; elsewhere the
// request is harmless (the kernel ignores it, or gives them anyway). Paired rates in
// doc/benchmarks.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace molchaos::sim {

/// v.assign(n, value), with the whole 2 MB pages of a new allocation of 4 MB or more advised for
/// huge pages before they are written.
template <class T>
void assign_in_huge_pages(std::vector<T>& v, std::size_t n, const T& value) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t k_huge_page = std::uintptr_t{2} << 20;
  if (n > v.capacity() && n * sizeof(T) >= 2 * k_huge_page) {
    std::vector<T>().swap(v);
    v.reserve(n);  // allocated, not yet touched
    const auto begin = reinterpret_cast<std::uintptr_t>(v.data());
    const std::uintptr_t first = (begin + k_huge_page - 1) & ~(k_huge_page - 1);
    const std::uintptr_t last = (begin + n * sizeof(T)) & ~(k_huge_page - 1);
    if (last > first)  // a hint: should it fail, the array keeps its small pages
      madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  }
#endif
  v.assign(n, value);
}

}  // namespace molchaos::sim
