// hypergas/dsmc/huge_pages.hpp -- ask the kernel to back a large array with huge pages.
//
// Random pair access to N = 1e6..1e7 velocities touches a new 4 KiB page almost every time,
// so besides the cache miss each access pays a TLB miss (doubly expensive under virtual
// machines' nested paging). Transparent huge pages (2 MiB) cover the whole array with a
// few TLB entries. The arrays are allocated and filled before the engine sees them, so we
// ask for a synchronous collapse of the already-populated range (MADV_COLLAPSE, Linux >=
// 6.1) after marking it MADV_HUGEPAGE. Purely a hint: any failure is ignored and nothing
// changes in the results.
#pragma once

#include <cstddef>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace hypergas::dsmc {

/// Advises huge pages for the 2 MiB-aligned interior of [p, p + bytes); no effect on other
/// systems or for arrays under 4 MiB.
inline void advise_huge_pages(void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t(1) << 21;
  if (bytes < 2 * huge) return;
  const auto a = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t b = (a + huge - 1) & ~(huge - 1);
  const std::uintptr_t e = (a + bytes) & ~(huge - 1);
  if (e <= b) return;
  (void)madvise(reinterpret_cast<void*>(b), e - b, MADV_HUGEPAGE);
#ifndef MADV_COLLAPSE
  constexpr int collapse = 25;  // Linux 6.1 value, absent from older headers
#else
  constexpr int collapse = MADV_COLLAPSE;
#endif
  (void)madvise(reinterpret_cast<void*>(b), e - b, collapse);
#else
  (void)p;
  (void)bytes;
#endif
}

}  // namespace hypergas::dsmc
