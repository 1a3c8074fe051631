// DefaultInitAllocator (base/default_init_allocator.h) whose large blocks (4 MiB and more) are
// aligned on 2 MiB and, on Linux, advised MADV_HUGEPAGE (madvise(2); the kernel's
// admin-guide/mm/transhuge): where the kernel's transparent huge pages are "always" or "madvise"
// (the common defaults) it backs them with 2 MiB pages, so a 32 MiB map costs 16 page faults
// instead of 8,192. glibc serves such blocks by mmap and returns them to the system when freed,
// so every bake paid those faults again (the 185k-face normal bake: about 8.8k faults a bake, 1.1k
// with this; perf stat over the benchmark's loop). Elsewhere, or where the kernel declines, the
// blocks are ordinary aligned ones. Smaller blocks are std::allocator's.
#pragma once

#include "base/default_init_allocator.h"

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace voxelfair {

template <class T>
struct HugePageAllocator : DefaultInitAllocator<T> {
    static constexpr size_t kHugePage = size_t(2) << 20;
    static constexpr size_t kLarge = size_t(4) << 20;
    template <class U>
    struct rebind {
        using other = HugePageAllocator<U>;
    };
    HugePageAllocator() noexcept = default;
    template <class U>
    explicit HugePageAllocator(const HugePageAllocator<U> & /*other*/) noexcept {}
    T *allocate(size_t n) {
        const size_t bytes = n * sizeof(T);
        if (n > SIZE_MAX / sizeof(T))
            throw std::bad_array_new_length();
        if (bytes < kLarge)
            return DefaultInitAllocator<T>::allocate(n);
        void *p = ::operator new(bytes, std::align_val_t(kHugePage));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        madvise(p, bytes, MADV_HUGEPAGE);  // advice: a refusal leaves ordinary pages
#endif
        return static_cast<T *>(p);
    }
    void deallocate(T *p, size_t n) noexcept {
        if (n * sizeof(T) < kLarge)
            DefaultInitAllocator<T>::deallocate(p, n);
        else
            ::operator delete(p, std::align_val_t(kHugePage));
    }
};
template <class T, class U>
bool operator==(const HugePageAllocator<T> & /*a*/, const HugePageAllocator<U> & /*b*/) noexcept {
    return true;
}
template <class T, class U>
bool operator!=(const HugePageAllocator<T> & /*a*/, const HugePageAllocator<U> & /*b*/) noexcept {
    return false;
}

// Bytes whose resize() leaves new bytes unwritten, on huge pages when large (a map's texels, a
// bake's per-texel states).
using ByteBuffer = std::vector<uint8_t, HugePageAllocator<uint8_t>>;

}  // namespace voxelfair
