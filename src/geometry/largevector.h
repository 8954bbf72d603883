// Vectors for results of a million elements (splines, fits): storage the kernel may back with 2 MB
// pages instead of 4 KB ones.
//
// A fresh 16 MB vector is 4096 pages of 4 KB, and the first write to each costs a page fault (a
// trap, the page's accounting and zeroing): measured ~1 µs a page with its zeroing here, a third of a
// million-point spline's time. Linux's transparent huge pages in "madvise" mode (the common default) back an
// anonymous range with 2 MB pages when asked by madvise(MADV_HUGEPAGE) before it is touched: 512
// times fewer faults (Linux admin-guide, "Transparent Hugepage Support"). The advice is only a hint:
// where huge pages are disabled or none are free, the range stays as it was. Elsewhere, and for
// small vectors, these are plain vectors.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace kontur::geo {

// Below this many bytes a vector does not span a whole 2 MB page worth advising.
inline constexpr std::size_t kLargeVectorBytes = std::size_t(4) << 20;

// Advises the kernel to back the whole 2 MB pages inside [data, data + bytes) with huge pages.
inline void adviseHugePages([[maybe_unused]] void *data, [[maybe_unused]] std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (bytes < kLargeVectorBytes)
        return;
    constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
    const auto begin = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t last = (begin + bytes) & ~(kHuge - 1);
    if (last > first)
        madvise(reinterpret_cast<void *>(first), last - first, MADV_HUGEPAGE); // a hint: failure is harmless
#endif
}

// A vector of n value-initialised elements (as std::vector<T>(n)), its storage advised before the
// first write.
template <typename T> std::vector<T> largeVector(std::size_t n)
{
    std::vector<T> v;
    v.reserve(n);
    adviseHugePages(v.data(), n * sizeof(T));
    v.resize(n);
    return v;
}

} // namespace kontur::geo
