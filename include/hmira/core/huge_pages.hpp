// hmira/core/huge_pages.hpp
// A hint that a large array about to be filled be backed by transparent huge pages (2 MiB).
// Filling fresh memory costs one page fault per 4 KiB page: for a 2M-triangle mesh that is
// ~60,000 faults, and they were half the time of reading one from a PLY file (measured in
// bench/io: 261 -> 124 ms with huge pages). With huge pages it is one fault per 2 MiB.
//
// Only a hint, and only where the C library offers it: a no-op without <sys/mman.h> or
// MADV_HUGEPAGE, when the kernel's transparent huge pages are "never", and for blocks under
// huge_page_min_bytes (a huge page zeroed for a few bytes costs more than it saves). Define
// HMIRA_NO_HUGE_PAGES to turn it off at compile time. Never changes what the program computes.
#pragma once

#include <cstddef>
#include <cstdint>

#if !defined(HMIRA_NO_HUGE_PAGES) && __has_include(<sys/mman.h>) && __has_include(<unistd.h>)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace hmira::detail {

/// Blocks smaller than this are left alone.
inline constexpr std::size_t huge_page_min_bytes = std::size_t{4} << 20;
/// The transparent huge page size (x86-64, and arm64 with 4 KiB pages).
inline constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;

/// Asks that the block [p, p + bytes) be backed by huge pages where it covers whole 2 MiB
/// pages, when first touched. Touched memory keeps its contents. O(1) (one madvise call);
/// never fails.
///
/// The advice covers every page the block touches, not only its whole 2 MiB pages: advice on
/// part of a mapping splits it in three, and glibc's realloc can then no longer move a large
/// block with one mremap (the range must lie in one mapping), so it copied it instead
/// (trivial_array's growth, measured 2.4x slower in bench/subdivision's reserve case).
inline void advise_huge_pages([[maybe_unused]] const void* p, [[maybe_unused]] std::size_t bytes) noexcept {
#if !defined(HMIRA_NO_HUGE_PAGES) && __has_include(<sys/mman.h>) && __has_include(<unistd.h>) && defined(MADV_HUGEPAGE)
    if (p == nullptr || bytes < huge_page_min_bytes) return;
    static const long page_size = ::sysconf(_SC_PAGESIZE);
    if (page_size <= 0) return;
    const auto page = static_cast<std::uintptr_t>(page_size);
    const auto begin = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t first = begin / page * page;
    const std::uintptr_t last = (begin + bytes + page - 1) / page * page;
    static_cast<void>(::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE));
#endif
}

/// v.reserve(n), and the reserved room advised as above: for output arrays that are then
/// filled by push_back. May throw what reserve throws.
template <class Vector>
void reserve_huge(Vector& v, std::size_t n) {
    v.reserve(n);
    advise_huge_pages(v.data(), v.capacity() * sizeof(typename Vector::value_type));
}

}  // namespace hmira::detail
