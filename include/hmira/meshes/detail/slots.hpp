// hmira/meshes/detail/slots.hpp
// Slot bookkeeping for hmira's meshes: a free list of deleted slots kept in the slots' own
// records (so freeing never allocates nor touches new memory), and a lazily zeroed array for per-slot data that is
// mostly zero (deleted flags,
// generation counts that let a kept handle tell its element from a later one in the same slot).
// Both cost nothing on a mesh that never deletes.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <utility>

namespace hmira::detail {

/// The deleted slots of one element kind, last freed first, threaded through the slots' own
/// records: each freed slot's record keeps the index of the slot freed before it (the owning
/// mesh says which record), as CGAL's Surface_mesh does. Freeing a slot therefore writes only
/// into memory the mesh already holds: a separate list of indices made a cold pass of 1M
/// deletions fault in 8 MB of fresh pages (half of kill_edge_face's time in bench/euler).
/// Never allocates; copies with the records.
class free_slots {
public:
    static constexpr std::uint32_t none = UINT32_MAX;  ///< the end of the list (a null handle's index)
    free_slots() = default;
    free_slots(const free_slots&) = default;
    free_slots& operator=(const free_slots&) = default;
    /// A moved-from list is empty, as the moved-from mesh's records are.
    free_slots(free_slots&& other) noexcept
        : head_(std::exchange(other.head_, none)), size_(std::exchange(other.size_, 0)) {}
    free_slots& operator=(free_slots&& other) noexcept {
        const std::uint32_t head = std::exchange(other.head_, none);
        const std::size_t size = std::exchange(other.size_, 0);
        head_ = head;
        size_ = size;
        return *this;
    }
    ~free_slots() = default;
    /// Frees slot i; `link` is the record of slot i that holds the list's next slot.
    void push(std::uint32_t i, std::uint32_t& link) noexcept {
        link = head_;
        head_ = i;
        ++size_;
    }
    bool empty() const noexcept { return size_ == 0; }
    std::size_t size() const noexcept { return size_; }
    /// The most recently freed slot. \pre !empty()
    std::uint32_t top() const noexcept { return head_; }
    /// Takes top() off the list; `link` is the value its record holds (read it before the
    /// slot's records are overwritten).
    void pop(std::uint32_t link) noexcept {
        head_ = link;
        --size_;
    }
    /// Forgets every slot.
    void clear() noexcept {
        head_ = none;
        size_ = 0;
    }

private:
    std::uint32_t head_ = none;
    std::size_t size_ = 0;
};

/// An array of T that reads as all zeros until written, held in memory from calloc: entries
/// past size() read as zero, and a large array that is only grown, never written, keeps its
/// pages unmapped (the kernel zeroes a page when it is first written, not before). The meshes
/// keep their deleted flags, slot generations and inner-ring indices in these, so that a mesh
/// that never deletes and has no holes pays for none of them. T is a trivially copyable integer.
template <class T>
class zeroed_array {
public:
    zeroed_array() = default;
    zeroed_array(const zeroed_array& other) {
        if (other.size_ == 0) return;
        data_ = allocate(other.size_);
        size_ = other.size_;
        dirty_ = other.dirty_;
        if (dirty_) std::memcpy(data_, other.data_, size_ * sizeof(T));
    }
    zeroed_array& operator=(const zeroed_array& other) {
        if (this != &other) {
            zeroed_array copy(other);
            swap(copy);
        }
        return *this;
    }
    zeroed_array(zeroed_array&& other) noexcept { swap(other); }
    zeroed_array& operator=(zeroed_array&& other) noexcept {
        zeroed_array moved(std::move(other));
        swap(moved);
        return *this;
    }
    ~zeroed_array() { std::free(data_); }

    /// Entry i, zero past the end. O(1).
    T operator[](std::size_t i) const noexcept { return i < size_ ? data_[i] : T{}; }
    /// The entries (null when none are held); size() of them.
    const T* data() const noexcept { return data_; }
    /// Number of entries held.
    std::size_t size() const noexcept { return size_; }
    /// Writes entry i. \pre i < size(). Never allocates.
    void set(std::size_t i, T value) noexcept {
        data_[i] = value;
        dirty_ = true;
    }
    /// Entry i for writing, holding at least `bound` entries if it must grow. May throw
    /// std::bad_alloc (then nothing changed). Amortised O(1).
    T& at(std::size_t i, std::size_t bound) {
        if (i >= size_) ensure(std::max(i + 1, bound));
        dirty_ = true;
        return data_[i];
    }
    /// Holds at least n entries, growing geometrically; the new ones read as zero. May throw
    /// std::bad_alloc (then nothing changed). An array never written is not copied.
    void ensure(std::size_t n) {
        if (n > size_) grow(n);  // the check inlines into every append; the growth stays out of line
    }
    /// Every entry zero again, with as many held (fresh pages rather than a pass of writes).
    /// May throw std::bad_alloc (then nothing changed).
    void zero() {
        if (!dirty_) return;
        T* p = allocate(size_);
        std::free(data_);
        data_ = p;
        dirty_ = false;
    }
    /// Holds nothing.
    void clear() noexcept {
        std::free(data_);
        data_ = nullptr;
        size_ = 0;
        dirty_ = false;
    }

private:
    [[gnu::noinline]] void grow(std::size_t n) {
        const std::size_t grown = std::max({n, 2 * size_, std::size_t{16}});
        T* p = allocate(grown);
        if (dirty_) std::memcpy(p, data_, size_ * sizeof(T));
        std::free(data_);
        data_ = p;
        size_ = grown;
    }
    static T* allocate(std::size_t n) {
        auto* p = static_cast<T*>(std::calloc(n, sizeof(T)));
        if (!p) throw std::bad_alloc();
        return p;
    }
    void swap(zeroed_array& other) noexcept {
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(dirty_, other.dirty_);
    }

    T* data_ = nullptr;
    std::size_t size_ = 0;
    bool dirty_ = false;  // some entry was written (else every entry is zero)
};

}  // namespace hmira::detail
