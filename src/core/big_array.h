// Arrays of a big scene -- a million triangles take hundreds of MB -- read
// at random by the BVH walk. On 4 KiB pages nearly every leaf or node it
// reads misses the TLB as well as the cache; on Linux's transparent 2 MiB
// pages one TLB entry covers 512 times as much. Where the kernel gives them
// only to memory that asks (THP "madvise", as on this machine), an array of
// 2 MiB or more is allocated on a 2 MiB boundary and asks. Measured: the
// 1.3-million-triangle frame of the scaling benchmark 7% faster in float and
// 10% in double (bench/bench_scaling.cpp). Elsewhere no hint is given.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace fh {

inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

template <typename T>
struct HugePageAllocator {
    using value_type = T;

    HugePageAllocator() = default;
    template <typename U>
    HugePageAllocator(const HugePageAllocator<U>&) {}

    T* allocate(std::size_t n) {
        if (n > std::size_t(-1) / sizeof(T)) throw std::bad_alloc();
        const std::size_t bytes = n * sizeof(T);
        if (bytes < kHugePageBytes) return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
        const std::size_t rounded = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
        void* p = std::aligned_alloc(kHugePageBytes, rounded);
        if (!p) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
        madvise(p, rounded, MADV_HUGEPAGE);  // a hint: refused or ignored, the pages stay small
#endif
        return static_cast<T*>(p);
    }

    void deallocate(T* p, std::size_t n) {
        if (n * sizeof(T) < kHugePageBytes) ::operator delete(p, std::align_val_t(alignof(T)));
        else std::free(p);
    }

    template <typename U>
    bool operator==(const HugePageAllocator<U>&) const {
        return true;
    }
};

// A vector whose storage, once 2 MiB or more, sits on huge pages.
template <typename T>
using BigArray = std::vector<T, HugePageAllocator<T>>;

}  // namespace fh
