// hmira/adapters/detail/index_support.hpp
// What the adapters share: the capability they start from (face lists), walking a face's
// sides without allocating, the stamp that lets an indexed adapter notice a changed mesh,
// and the compact CSR arrays its answers are read from.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"

namespace hmira {

/// What every adapter of this folder needs from a mesh: live faces with their ordered
/// vertices (thesis 7.2.1) and dense vertex and face indices for its scratch arrays.
template <class M, class T = default_traits<M>>
concept adapter_source_mesh =
    face_vertex_range_mesh<M, T> && vertex_list_mesh<M, T> && vertex_index_mesh<M, T> && face_index_mesh<M, T>;

/// An indexed adapter also needs to know when the mesh changed (change_counted_mesh).
template <class M, class T = default_traits<M>>
concept indexed_adapter_source_mesh = adapter_source_mesh<M, T> && change_counted_mesh<M, T>;

namespace detail {

/// Calls side(a, b) for every side a -> b of f's loop, in winding order. No allocation.
template <class M, class T, class F>
void for_each_side(const M& m, typename T::face_handle f, F&& side) {
    using V = typename T::vertex_handle;
    bool started = false;
    V first{}, last{};
    for (V w : T::face_vertices(m, f)) {
        if (!started) {
            first = w;
            started = true;
        } else {
            side(last, w);
        }
        last = w;
    }
    if (started && !(first == last)) side(last, first);
}

/// Records which mesh an index was built from and its change count at that time; check()
/// throws hmira_error when either differs, so a stale index never answers.
template <class M, class T>
class index_stamp {
public:
    index_stamp() = default;
    index_stamp(const M& m, const char* who)
        : mesh_(&m), count_(static_cast<std::uint64_t>(T::change_count(m))), who_(who) {}

    void check(const M& m) const {
        if (&m != mesh_) [[unlikely]]
            throw hmira_error(fail(errc::invalid_argument,
                                   std::string(who_) + ": queried with a mesh other than the one it was built from"));
        const auto now = static_cast<std::uint64_t>(T::change_count(m));
        if (now != count_) [[unlikely]]
            throw hmira_error(fail(errc::invalid_argument,
                                   std::string(who_) + ": the mesh changed since the index was built (change count " +
                                       std::to_string(now) + ", built at " + std::to_string(count_) +
                                       "); rebuild the adapter (adapted_mesh::refresh())"));
    }
    bool is_current(const M& m) const {
        return &m == mesh_ && static_cast<std::uint64_t>(T::change_count(m)) == count_;
    }

private:
    const M* mesh_ = nullptr;
    std::uint64_t count_ = 0;
    const char* who_ = "indexed adapter";
};

/// Compressed rows: row r is values[offsets[r] .. offsets[r + 1]).
template <class Value>
struct csr {
    std::vector<std::uint32_t> offsets{0};
    std::vector<Value> values;

    std::span<const Value> row(std::size_t r) const {
        if (r + 1 >= offsets.size()) return {};
        return {values.data() + offsets[r], values.data() + offsets[r + 1]};
    }
    std::size_t memory_bytes() const {
        return offsets.capacity() * sizeof(std::uint32_t) + values.capacity() * sizeof(Value);
    }
};

/// Builds a CSR with `rows` rows from (row, value) pairs produced by emit(push) twice: once
/// counting, once filling. O(rows + pairs).
template <class Value, class Emit>
csr<Value> build_csr(std::size_t rows, Emit&& emit) {
    csr<Value> out;
    out.offsets.assign(rows + 1, 0);
    emit([&](std::size_t r, const Value&) { ++out.offsets[r + 1]; });
    for (std::size_t r = 0; r < rows; ++r) out.offsets[r + 1] += out.offsets[r];
    out.values.resize(out.offsets[rows]);
    std::vector<std::uint32_t> cursor(out.offsets.begin(), out.offsets.end() - 1);
    emit([&](std::size_t r, const Value& v) { out.values[cursor[r]++] = v; });
    return out;
}

/// Handle of every live vertex, by vertex index (traits give index from handle, not back).
template <class M, class T>
std::vector<typename T::vertex_handle> vertex_handles_by_index(const M& m) {
    std::vector<typename T::vertex_handle> out(T::vertex_index_bound(m));
    for (auto v : T::vertices(m)) out[T::vertex_index(m, v)] = v;
    return out;
}

}  // namespace detail
}  // namespace hmira
