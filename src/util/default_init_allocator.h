#pragma once
// std::allocator, except that resize() default-initialises new elements instead of
// value-initialising them: trivial elements are left unwritten, for code that fills them itself
// (in parallel, say) and would otherwise pay for a single-threaded pass of zeros first.
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace lightpath {

template <typename T>
struct DefaultInitAllocator : std::allocator<T> {
    template <typename U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };
    using std::allocator<T>::allocator;

    template <typename U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        std::allocator_traits<std::allocator<T>>::construct(static_cast<std::allocator<T>&>(*this), p,
                                                            std::forward<Args>(args)...);
    }
};

}  // namespace lightpath
