// Large arrays that a build writes from start to end: their pages faulted in at once, on 2 MiB pages
// where the system offers them.
//
// Fresh memory costs a page fault at its first touch: one per 4 KiB page, each a trip into the kernel (and,
// in a virtual machine, often one into the host). A wide BVH of Sponza writes 16 MiB of triangle blocks,
// 4,000 faults, which were most of the collapse's time (chapter 13's NOTES.md). Two requests cut that:
//   - madvise(MADV_HUGEPAGE) for arrays of 2 MiB or more: Linux hands out transparent huge pages to memory
//     that asks for them (/sys/kernel/mm/transparent_hugepage/enabled reads "madvise" or "always"), one
//     fault per 2 MiB. Embree's allocator asks the same way (os_malloc).
//   - madvise(MADV_POPULATE_WRITE) (Linux 5.14) for arrays of 64 KiB or more: every page of the array
//     faulted in by one call, before the build writes it, instead of one trap per page.
// Both are advice: where the kernel refuses, the memory works as before. Populating touches the whole
// allocation, so an array should be allocated at the size it will fill (reserve the exact count, not a
// bound). Arrays under 64 KiB come from the ordinary allocator; larger ones are rounded up to 4 KiB pages
// and aligned to one (to 2 MiB from 2 MiB on); their whole 2 MiB stretches get huge pages, the rest 4 KiB
// ones, so that the memory they hold is their size.
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <stdlib.h>
#include <memory>
#include <new>
#include <vector>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace strahl {

// Whether huge_page_allocator gives its advice (true unless a program turns it off to measure what it
// changes: the race's --plain-pages). Read when an array is allocated.
inline std::atomic<bool> page_advice{true};

template <class T>
struct huge_page_allocator {
    using value_type = T;
    static constexpr std::size_t huge_page = std::size_t(2) << 20, page = 4096;
    static constexpr std::size_t at_least = std::size_t(64) << 10;  // smaller arrays: the ordinary allocator

    huge_page_allocator() = default;
    template <class U>
    huge_page_allocator(const huge_page_allocator<U>&) {}

    // Decided by the size alone, so that deallocate() knows where the array came from.
    static bool large(std::size_t n) { return n >= at_least / sizeof(T); }

    T* allocate(std::size_t n) {
        if (!large(n)) return std::allocator<T>{}.allocate(n);
        if (n > (std::size_t(-1) - huge_page) / sizeof(T)) throw std::bad_array_new_length();
        // The array's own pages (rounded up to 4 KiB), starting on a 2 MiB boundary when it spans one.
        const std::size_t bytes = (n * sizeof(T) + page - 1) & ~(page - 1);
        const std::size_t align = bytes >= huge_page ? huge_page : page;
        void* p = nullptr;
        if (::posix_memalign(&p, align, bytes) != 0) throw std::bad_alloc();
#if defined(__linux__)
        if (!page_advice.load(std::memory_order_relaxed)) return static_cast<T*>(p);
        // Advice only: where the kernel refuses (an older one, no THP), the pages come one fault at a time.
        // Huge pages for the whole 2 MiB stretches only: the tail stays on 4 KiB pages, so the memory held
        // is the array's (a huge page over the tail would hold up to 2 MiB more).
#if defined(MADV_HUGEPAGE)
        if (bytes >= huge_page) ::madvise(p, bytes & ~(huge_page - 1), MADV_HUGEPAGE);
#endif
#if defined(MADV_POPULATE_WRITE)
        ::madvise(p, bytes, MADV_POPULATE_WRITE);
#endif
#endif
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t n) noexcept {
        if (!large(n)) return std::allocator<T>{}.deallocate(p, n);
        std::free(p);
    }
    template <class U>
    bool operator==(const huge_page_allocator<U>&) const noexcept { return true; }
};

template <class T>
using huge_vector = std::vector<T, huge_page_allocator<T>>;

}  // namespace strahl
