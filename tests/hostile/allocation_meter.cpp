#include "allocation_meter.h"

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace voxelfair::test {
namespace {

std::atomic<size_t> live{0};
std::atomic<size_t> peak{0};

void *allocate(size_t size) noexcept {
    void *p = std::malloc(size == 0 ? 1 : size);
    if (p == nullptr)
        return nullptr;
    // The block's real size, so that delete (often unsized) subtracts exactly what was added.
    const size_t bytes = malloc_usable_size(p);
    const size_t now = live.fetch_add(bytes, std::memory_order_relaxed) + bytes;
    size_t seen = peak.load(std::memory_order_relaxed);
    while (now > seen && !peak.compare_exchange_weak(seen, now, std::memory_order_relaxed)) {
    }
    return p;
}

void release(void *p) noexcept {
    if (p == nullptr)
        return;
    live.fetch_sub(malloc_usable_size(p), std::memory_order_relaxed);
    std::free(p);
}

}  // namespace

size_t liveHeapBytes() { return live.load(std::memory_order_relaxed); }

AllocationMeter::AllocationMeter() : baseline_(live.load(std::memory_order_relaxed)) {
    peak.store(baseline_, std::memory_order_relaxed);
}

AllocationMeter::~AllocationMeter() = default;

size_t AllocationMeter::peakBytes() const {
    const size_t p = peak.load(std::memory_order_relaxed);
    return p > baseline_ ? p - baseline_ : 0;
}

}  // namespace voxelfair::test

// The replaceable global allocation functions ([new.delete]); the aligned forms keep their
// defaults (nothing under test over-aligns).
void *operator new(size_t size) {
    if (void *p = voxelfair::test::allocate(size))
        return p;
    throw std::bad_alloc();
}
void *operator new[](size_t size) { return operator new(size); }
void *operator new(size_t size, const std::nothrow_t &) noexcept { return voxelfair::test::allocate(size); }
void *operator new[](size_t size, const std::nothrow_t &) noexcept { return voxelfair::test::allocate(size); }
void operator delete(void *p) noexcept { voxelfair::test::release(p); }
void operator delete[](void *p) noexcept { voxelfair::test::release(p); }
void operator delete(void *p, size_t) noexcept { voxelfair::test::release(p); }
void operator delete[](void *p, size_t) noexcept { voxelfair::test::release(p); }
void operator delete(void *p, const std::nothrow_t &) noexcept { voxelfair::test::release(p); }
void operator delete[](void *p, const std::nothrow_t &) noexcept { voxelfair::test::release(p); }
