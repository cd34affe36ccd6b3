// glibc's malloc on transparent 2 MiB pages. A first touch of each fresh
// 4 KiB page is a page fault, and on a virtual machine a fault is dear: on
// the AMD EPYC VM of 2026-11-29 about 10 us (a 100 MB array: 265 ms to
// touch on small pages, 12 ms on huge ones). Preparing Debian's
// 2CylinderEngine.glb in double touches ~15,000 fresh pages among its many
// per-mesh arrays, each too small for core/big_array.h's huge pages.
//
// So, before anything is allocated: blocks up to 32 MiB come from malloc's
// heap (not from mmap, which hands them back at free and faults them in
// again next time), freed memory stays there, every thread shares the one
// heap, and the heap's first kHeapReserve bytes -- reserved address space,
// committed only as touched -- ask for huge pages. Where the kernel gives
// them only to memory that asks (THP "madvise", the usual setting), that is
// what gets them.
#include "cli/huge_page_malloc.h"

#include <cstdint>
#include <cstdlib>  // first: defines __GLIBC__ on glibc
#include <cstring>

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace fh {

void use_huge_page_malloc() {
#if defined(__linux__) && defined(__GLIBC__) && defined(MADV_HUGEPAGE)
    // Not under valgrind, whose malloc is its own.
    const char* preload = std::getenv("LD_PRELOAD");
    if (preload && std::strstr(preload, "vgpreload")) return;
    constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
    constexpr std::size_t kHeapReserve = std::size_t(1) << 30;
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, int(kHeapReserve));
    mallopt(M_ARENA_MAX, 1);
    mallopt(M_TOP_PAD, int(kHeapReserve));
    const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(sbrk(0));
    {  // grows the heap by kHeapReserve, kept (volatile: a malloc freed unused may be left out)
        void* volatile block = std::malloc(std::size_t(16) << 20);
        std::free(block);
    }
    const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(sbrk(0));
    mallopt(M_TOP_PAD, 128 << 10);  // later growth: glibc's default pad (mallopt(3))
    const std::uintptr_t from = (start + kHuge - 1) & ~(kHuge - 1);
    if (end > from) madvise(reinterpret_cast<void*>(from), end - from, MADV_HUGEPAGE);  // a hint
#endif
}

}  // namespace fh
