// hmira/meshes/detail/trivial_array.hpp
// A growable array of trivially copyable records held in std::malloc/std::realloc memory, for a
// mesh's per-element connectivity. Growing a large block through realloc lets the C library
// extend it in place or move its pages without copying them (glibc remaps them), and a new
// element is written once, by the code that appends it, rather than zeroed first. The elements
// start on a cache-line boundary (see trivial_array).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <type_traits>
#include <utility>

#include "../../core/huge_pages.hpp"

namespace hmira::detail {

/// A std::vector-like array of T for the meshes' element records. T must be trivially copyable
/// and trivially destructible, so that the bytes may be moved by realloc and copied by memcpy,
/// and of implicit-lifetime type (an aggregate, or with a trivial copy constructor), so that
/// the objects exist in memory from malloc/realloc without being constructed (C++20 [intro.object]).
/// Every operation that allocates may throw std::bad_alloc and then leaves the array unchanged.
/// Growth is geometric: push_back is amortised O(1).
///
/// The elements start on a 64-byte (cache-line) boundary, although malloc/realloc promise only
/// 16: a large block from glibc starts 16 bytes past a page boundary, which made every other
/// 32-byte pair of halfedge records (an edge's two halves) straddle two cache lines, so a walk
/// around a vertex missed twice as often on those. The block is allocated `line` bytes larger
/// and the elements placed at the first boundary in it; when realloc returns a block whose
/// boundary sits at another offset, the elements are moved there (O(size); a block that
/// mremap moves keeps its offset within the page, so large arrays never need it).
template <class T>
class trivial_array {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "trivial_array holds trivially copyable records only; use std::vector for others");

public:
    trivial_array() = default;
    trivial_array(const trivial_array& other) {
        if (other.size_ == 0) return;
        reallocate(other.size_);
        std::memcpy(static_cast<void*>(data_), other.data_, other.size_ * sizeof(T));
        size_ = other.size_;
    }
    trivial_array& operator=(const trivial_array& other) {
        if (this != &other) {
            trivial_array copy(other);
            swap(copy);
        }
        return *this;
    }
    trivial_array(trivial_array&& other) noexcept { swap(other); }
    trivial_array& operator=(trivial_array&& other) noexcept {
        trivial_array moved(std::move(other));
        swap(moved);
        return *this;
    }
    ~trivial_array() { std::free(block_); }

    /// Element access and iteration (raw pointers, so the array is a contiguous range).
    ///@{
    T& operator[](std::size_t i) noexcept { return data_[i]; }
    const T& operator[](std::size_t i) const noexcept { return data_[i]; }
    T* data() noexcept { return data_; }
    const T* data() const noexcept { return data_; }
    T* begin() noexcept { return data_; }
    T* end() noexcept { return data_ + size_; }
    const T* begin() const noexcept { return data_; }
    const T* end() const noexcept { return data_ + size_; }
    ///@}
    /// Number of elements, room before the next allocation, emptiness.
    ///@{
    std::size_t size() const noexcept { return size_; }
    std::size_t capacity() const noexcept { return capacity_; }
    bool empty() const noexcept { return size_ == 0; }
    ///@}

    /// Room for n elements without reallocating; the elements held keep their values (moved by
    /// realloc, which need not copy them). O(1) besides what realloc does.
    void reserve(std::size_t n) {
        if (n > capacity_) reallocate(n);
    }
    /// Room for n elements, grown geometrically (as push_back grows): what an append of several
    /// elements calls first, so that none of them can fail once one is in. Amortised O(1).
    void ensure_room(std::size_t n) {
        if (n > capacity_) grow(n);
    }
    /// Appends v. Amortised O(1).
    void push_back(const T& v) {
        if (size_ == capacity_) {
            const T copy = v;  // v may live in this array, which grow() may move
            grow(size_ + 1);
            data_[size_++] = copy;
            return;
        }
        data_[size_++] = v;
    }
    /// n elements: the first min(n, size()) keep their values, new ones are `value`. A shrink
    /// keeps the room. O(n - size()) when it grows.
    void resize(std::size_t n, const T& value = T{}) {
        if (n > size_) {
            const T copy = value;
            reserve(n);
            std::fill(data_ + size_, data_ + n, copy);
        }
        size_ = n;
    }
    /// n elements, those past size() left unwritten for the caller to write before it reads
    /// them (no fill pass over memory about to be overwritten). O(1) besides the allocation.
    void resize_for_overwrite(std::size_t n) {
        reserve(n);
        size_ = n;
    }
    /// n elements, all `value`. O(n).
    void assign(std::size_t n, const T& value) {
        const T copy = value;
        reserve(n);
        std::fill(data_, data_ + n, copy);
        size_ = n;
    }
    /// Holds no elements and keeps the room.
    void clear() noexcept { size_ = 0; }

private:
    [[gnu::noinline]] void grow(std::size_t n) { reallocate(std::max({n, 2 * capacity_, std::size_t{16}})); }
    static constexpr std::size_t line = 64;
    // Room for n elements in a block `line` bytes larger, the elements at its first line
    // boundary; on failure nothing changes.
    void reallocate(std::size_t n) {
        // No object may exceed PTRDIFF_MAX bytes (which the compiler also checks realloc against).
        constexpr auto max_bytes = static_cast<std::size_t>(std::numeric_limits<std::ptrdiff_t>::max());
        if (n > (max_bytes - line) / sizeof(T)) throw std::bad_alloc();
        const std::size_t old_offset = block_ ? static_cast<std::size_t>(reinterpret_cast<char*>(data_) - block_) : 0;
        void* q = std::realloc(static_cast<void*>(block_), n * sizeof(T) + line);
        if (!q) throw std::bad_alloc();
        char* block = static_cast<char*>(q);
        advise_huge_pages(block, n * sizeof(T) + line);  // the room is filled next: fewer page faults
        const std::size_t offset = (line - reinterpret_cast<std::uintptr_t>(block) % line) % line;
        // realloc kept the bytes at their old offset in the block; move them to the boundary.
        if (offset != old_offset && size_ > 0) std::memmove(block + offset, block + old_offset, size_ * sizeof(T));
        block_ = block;
        data_ = reinterpret_cast<T*>(block + offset);
        capacity_ = n;
    }
    void swap(trivial_array& other) noexcept {
        std::swap(block_, other.block_);
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(capacity_, other.capacity_);
    }

    char* block_ = nullptr;  // what realloc returned; data_ is its first line boundary
    T* data_ = nullptr;
    std::size_t size_ = 0, capacity_ = 0;
};

}  // namespace hmira::detail
