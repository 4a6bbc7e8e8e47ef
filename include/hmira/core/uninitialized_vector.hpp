// hmira/core/uninitialized_vector.hpp
// A std::vector whose resize() leaves the new elements unwritten, for outputs that a parallel
// pass fills completely: zero-filling them first would be a serial pass over the whole output
// (and would touch every page on one thread), for values that are all overwritten anyway.
#pragma once

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "huge_pages.hpp"

namespace hmira {

/// std::allocator, except that constructing an element without arguments does nothing: the
/// element keeps whatever the memory held. Only for trivially copyable, trivially destructible
/// types (vec3, std::array of numbers), whose objects exist as soon as the memory is allocated.
/// Constructing with arguments (push_back, insert, resize with a value) behaves as usual.
template <class T>
struct uninitialized_allocator : std::allocator<T> {
    /// The element type.
    using value_type = T;
    /// The same allocator for another element type.
    template <class U>
    struct rebind {
        using other = uninitialized_allocator<U>;  ///< the allocator for U
    };

    /// Default, and converting from the allocator of another element type (stateless).
    ///@{
    constexpr uninitialized_allocator() noexcept = default;
    template <class U>
    constexpr uninitialized_allocator(const uninitialized_allocator<U>&) noexcept {}
    ///@}

    /// Room for n elements; a large block is advised to be backed by huge pages, since the
    /// arrays held in it are outputs that are filled whole (see huge_pages.hpp).
    T* allocate(std::size_t n) {
        T* p = std::allocator<T>::allocate(n);
        detail::advise_huge_pages(p, n * sizeof(T));
        return p;
    }

    /// Leaves `*p` unwritten.
    template <class U>
    void construct(U*) noexcept {
        static_assert(std::is_trivially_copyable_v<U> && std::is_trivially_destructible_v<U>,
                      "uninitialized_allocator leaves elements unwritten: only for trivially copyable types");
    }
    /// Constructs `*p` from `args`, as std::allocator_traits would.
    template <class U, class... Args>
        requires(sizeof...(Args) > 0)
    void construct(U* p, Args&&... args) {
        std::construct_at(p, std::forward<Args>(args)...);
    }

    /// Stateless: any two compare equal, so moves and swaps never copy elements.
    friend constexpr bool operator==(const uninitialized_allocator&, const uninitialized_allocator&) noexcept {
        return true;
    }
};

/// A std::vector whose resize(n) and vector(n) leave the new elements unwritten; everything
/// else is std::vector's. Reading an element before writing it is undefined: write every one first.
template <class T>
using uninitialized_vector = std::vector<T, uninitialized_allocator<T>>;

}  // namespace hmira
