// hmira/algorithms/decimation/detail/indexed_heap.hpp
// A binary min-heap of (cost, key) pairs whose keys are dense indices, with each key's place
// kept so that a key's cost can change or the key leave in O(log n): the decimation queue.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hmira::detail::decimation {

/// Min-heap over keys in [0, bound). Ties are broken by the smaller key, so the order of
/// removal depends on the costs and keys alone (deterministic).
class indexed_heap {
public:
    static constexpr std::uint32_t absent = 0xffffffffu;

    /// Room for keys in [0, bound), all absent. O(bound).
    explicit indexed_heap(std::size_t bound) : place_(bound, absent) { entries_.reserve(bound); }

    bool empty() const noexcept { return entries_.empty(); }
    std::size_t size() const noexcept { return entries_.size(); }
    bool contains(std::uint32_t key) const noexcept { return place_[key] != absent; }
    std::uint32_t top_key() const noexcept { return entries_.front().key; }
    double top_cost() const noexcept { return entries_.front().cost; }

    /// Inserts the key or changes its cost. O(log n).
    void set(std::uint32_t key, double cost) {
        std::uint32_t i = place_[key];
        if (i == absent) {
            i = std::uint32_t(entries_.size());
            entries_.push_back({cost, key});
            place_[key] = i;
            up(i);
            return;
        }
        const bool lower = before({cost, key}, entries_[i]);
        entries_[i].cost = cost;
        lower ? up(i) : down(i);
    }

    /// Removes the key if present. O(log n).
    void erase(std::uint32_t key) {
        const std::uint32_t i = place_[key];
        if (i == absent) return;
        place_[key] = absent;
        const entry last = entries_.back();
        entries_.pop_back();
        if (i == entries_.size()) return;
        entries_[i] = last;
        place_[last.key] = i;
        if (i > 0 && before(last, entries_[(i - 1) / 2]))
            up(i);
        else
            down(i);
    }

private:
    struct entry {
        double cost;
        std::uint32_t key;
    };
    static bool before(const entry& a, const entry& b) noexcept {
        return a.cost < b.cost || (a.cost == b.cost && a.key < b.key);
    }
    void up(std::uint32_t i) {
        const entry e = entries_[i];
        while (i > 0) {
            const std::uint32_t parent = (i - 1) / 2;
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
        const std::size_t n = entries_.size();
        for (;;) {
            std::size_t child = 2 * std::size_t(i) + 1;
            if (child >= n) break;
            if (child + 1 < n && before(entries_[child + 1], entries_[child])) ++child;
            if (!before(entries_[child], e)) break;
            entries_[i] = entries_[child];
            place_[entries_[i].key] = i;
            i = std::uint32_t(child);
        }
        entries_[i] = e;
        place_[e.key] = i;
    }

    std::vector<entry> entries_;
    std::vector<std::uint32_t> place_;
};

}  // namespace hmira::detail::decimation
