// A std::allocator whose value-less construct() default-initialises (leaves a byte or a float
// as it is) instead of value-initialising (zeroing): resize() of a large buffer that is written
// in full afterwards does not write it twice nor touch its pages on the resizing thread (their
// first touch, the kernel's page faults, happens where the buffer is filled: the bands of the
// bakes). Any other construct() is std::allocator's. The "default-init allocator" idiom
// (e.g. Boost.Container's default_init_t, C++20 std::make_unique_for_overwrite).
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace voxelfair {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };
    DefaultInitAllocator() noexcept = default;
    template <class U>
    explicit DefaultInitAllocator(const DefaultInitAllocator<U> & /*other*/) noexcept {}
    template <class U>
    void construct(U *p) noexcept(std::is_nothrow_default_constructible<U>::value) {
        ::new (static_cast<void *>(p)) U;
    }
    template <class U, class... Args>
    void construct(U *p, Args &&...args) {
        ::new (static_cast<void *>(p)) U(std::forward<Args>(args)...);
    }
};

}  // namespace voxelfair
