// hmira/algorithms/decimation/detail/indexed_heap.hpp
// A 4-ary min-heap of (cost, key) pairs whose keys are dense indices, with each key's place
// kept so that a key's cost can change or the key leave in O(log n): the decimation queue.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

#include "../../../core/huge_pages.hpp"

namespace hmira::detail::decimation {

/// Min-heap over keys in [0, bound). Ties are broken by the smaller key, so the order of
/// removal depends on the costs and keys alone (deterministic), whatever the heap's shape.
///
/// Four children per node, the four siblings sharing one 64-byte cache line: half the depth
/// of a binary heap, and one line fetched per level on the way down. Removing the top (the
/// decimation's most frequent operation on a queue far larger than the caches) walks the
/// whole depth, so its cache misses are the heap's cost.
class indexed_heap {
public:
    static constexpr std::uint32_t absent = 0xffffffffu;

    /// Room for keys in [0, bound), all absent. O(bound).
    explicit indexed_heap(std::size_t bound)
        : storage_(static_cast<entry*>(::operator new[]((bound + pad + 1) * sizeof(entry), std::align_val_t{64}))),
          entries_(storage_.get() + pad) {
        // Both arrays are read at random places: huge pages keep their address translations in the TLB.
        advise_huge_pages(storage_.get(), (bound + pad + 1) * sizeof(entry));
        reserve_huge(place_, bound);
        place_.assign(bound, absent);
    }

    bool empty() const noexcept { return size_ == 0; }
    std::size_t size() const noexcept { return size_; }
    bool contains(std::uint32_t key) const noexcept { return place_[key] != absent; }
    std::uint32_t top_key() const noexcept { return entries_[0].key; }
    double top_cost() const noexcept { return entries_[0].cost; }

    /// Cache hints for a coming set() or erase() of the key: the key's place, then (once that has
    /// arrived) its entry. No effect on the contents.
    void prefetch_place([[maybe_unused]] std::uint32_t key) const noexcept {
#if defined(__GNUC__) || defined(__clang__)
        __builtin_prefetch(&place_[key]);
#endif
    }
    void prefetch_entry([[maybe_unused]] std::uint32_t key) const noexcept {
#if defined(__GNUC__) || defined(__clang__)
        if (const std::uint32_t i = place_[key]; i != absent) __builtin_prefetch(&entries_[i]);
#endif
    }

    /// Inserts the key or changes its cost. O(log n).
    void set(std::uint32_t key, double cost) {
        std::uint32_t i = place_[key];
        if (i == absent) {
            i = size_++;
            entries_[i] = {cost, key};
            up(i);
            return;
        }
        const bool lower = before({cost, key}, entries_[i]);
        entries_[i].cost = cost;
        lower ? up(i) : down(i);
    }

    /// Appends an absent key without ordering; heapify() restores the order once all are in.
    /// O(1).
    void append(std::uint32_t key, double cost) {
        place_[key] = size_;
        entries_[size_++] = {cost, key};
    }

    /// Orders the entries (Floyd's bottom-up construction). O(n).
    void heapify() {
        if (size_ < 2) return;
        for (std::uint32_t i = (size_ - 2) / arity + 1; i-- > 0;) down(i);
    }

    /// Removes the key if present. O(log n).
    void erase(std::uint32_t key) {
        const std::uint32_t i = place_[key];
        if (i == absent) return;
        place_[key] = absent;
        const entry last = entries_[--size_];
        if (i == size_) return;
        entries_[i] = last;
        if (i > 0 && before(last, entries_[(i - 1) / arity]))
            up(i);
        else
            down(i);
    }

private:
    struct entry {
        double cost;
        std::uint32_t key;
    };
    static_assert(sizeof(entry) == 16);
    static constexpr std::uint32_t arity = 4;
    // Entry i's children are 4i+1 .. 4i+4; three entries in front of the root put every group
    // of siblings at a multiple of four entries (64 bytes) from the aligned allocation.
    static constexpr std::size_t pad = 3;
    struct aligned_delete {
        void operator()(entry* p) const noexcept { ::operator delete[](p, std::align_val_t{64}); }
    };

    static bool before(const entry& a, const entry& b) noexcept {
        return a.cost < b.cost || (a.cost == b.cost && a.key < b.key);
    }
    void up(std::uint32_t i) {
        const entry e = entries_[i];
        while (i > 0) {
            const std::uint32_t parent = (i - 1) / arity;
            if (!before(e, entries_[parent])) break;
            entries_[i] = entries_[parent];
            place_[entries_[i].key] = i;
            i = parent;
        }
        entries_[i] = e;
        place_[e.key] = i;
    }
    void down(std::uint32_t i) {
        const entry e = entries_[i];
        const std::size_t n = size_;
        for (;;) {
            const std::size_t first = arity * std::size_t(i) + 1;
            if (first >= n) break;
            std::size_t child = first;
            const std::size_t last = first + arity < n ? first + arity : n;
#if defined(__GNUC__) || defined(__clang__)
            // The next level's candidates, whichever child wins: their lines arrive while
            // this level is compared.
            for (std::size_t c = first; c < last && arity * c + 1 < n; ++c)
                __builtin_prefetch(&entries_[arity * c + 1]);
#endif
            for (std::size_t c = first + 1; c < last; ++c)
                if (before(entries_[c], entries_[child])) child = c;
            if (!before(entries_[child], e)) break;
            entries_[i] = entries_[child];
            place_[entries_[i].key] = i;
            i = std::uint32_t(child);
        }
        entries_[i] = e;
        place_[e.key] = i;
    }

    std::vector<std::uint32_t> place_;
    std::unique_ptr<entry[], aligned_delete> storage_;
    entry* entries_;
    std::uint32_t size_ = 0;
};

}  // namespace hmira::detail::decimation
