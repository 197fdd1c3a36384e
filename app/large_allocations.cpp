// SPDX-License-Identifier: Apache-2.0
// Large blocks in transparent huge pages. The kernel takes a fault, zeroes and maps every 4 KiB
// page on its first touch, and at a million patches those faults are a large part of loading
// and setup (docs/performance.md, "Memory of the 10^6-patch office"). This replaces the global
// operator new of the hmcr executable only: every block of 4 MiB or more that C++ allocates
// (OpenMesh's arrays, the OBJ text, the element roots, the shaded mesh's arrays that the .vtp
// writer reads in place, the geometry buffers Embree shares) is advised into 2 MiB pages before it
// is touched, so it takes 512 times fewer faults. What VTK and Embree allocate themselves (VTK's
// own arrays with malloc, Embree's BVH) is not. The block comes from malloc as before and goes back
// through free (the default operator delete); the advice changes speed, never contents. Off under
// the sanitizers, which own operator new.
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__) && !defined(HMCR_NO_HUGE_PAGES)
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define HMCR_NO_HUGE_PAGES
#endif
#endif
#endif

#ifndef HMCR_NO_HUGE_PAGES
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;
constexpr std::size_t kLarge = std::size_t(4) << 20;  // below, not worth a system call

}  // namespace

void* operator new(std::size_t n) {
    void* p = std::malloc(n > 0 ? n : 1);
    if (p == nullptr) throw std::bad_alloc();
    if (n >= kLarge) {
        const auto at = reinterpret_cast<std::uintptr_t>(p);
        const std::uintptr_t begin = (at + kHugePage - 1) & ~(kHugePage - 1);
        const std::uintptr_t end = (at + n) & ~(kHugePage - 1);
        madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice only
    }
    return p;
}
#endif
