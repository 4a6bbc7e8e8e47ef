// hmira/algorithms/editing/detail/editing_common.hpp
// What truncate, bevel and extrude share: the editing concept, small geometry helpers, and
// two composite operators built from the Euler operators (split an edge, replace a vertex by a
// polygon through its neighbours). Not part of the public API.
#pragma once

#include <algorithm>
#include <bit>
#include <concepts>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "../../../concepts.hpp"
#include "../../geometry/face_normal.hpp"
#include "../../../core/progress.hpp"
#include "../../../core/result.hpp"
#include "../../../core/vec3.hpp"
#include "../../euler/euler.hpp"
#include "transaction.hpp"

namespace hmira {

/// A mesh the editing functions (truncate, bevel, extrude) can change: the Euler operators'
/// mesh (halfedge navigation and raw halfedge mutation, polygons of any degree, so a
/// triangles-only model is rejected) with positions, and dense vertex, edge and face indices
/// for the local scratch sets that selections of several elements need.
template <class M, class T = default_traits<M>>
concept editable_mesh = euler_mutable_mesh<M, T> && positioned_mesh<M, T> && vertex_index_mesh<M, T> &&
                        edge_index_mesh<M, T> && face_index_mesh<M, T> && halfedge_index_mesh<M, T>;

namespace detail::editing {

template <class M, class T>
using point = vec3<typename T::scalar>;

template <class M, class T>
vec3<double> pos(const M& m, typename T::vertex_handle v) {
    const vec3<typename T::scalar> p = T::position(m, v);
    return {double(p.x), double(p.y), double(p.z)};
}

template <class M, class T>
point<M, T> to_point(const vec3<double>& p) {
    using S = typename T::scalar;
    return {static_cast<S>(p.x), static_cast<S>(p.y), static_cast<S>(p.z)};
}

/// Room for an edit that creates up to this many vertices, edges and faces, in the mesh
/// (the traits' optional reserve, as index bounds) and in the active journal (JT's optional
/// reserve_journal), so that a whole-mesh edit never reallocates half way: growing vectors of
/// millions of elements copies them and faults in fresh pages, which makes such edits
/// superlinear. Only when the edit grows the mesh by at least an eighth: a loop of small
/// edits would otherwise reallocate (exact reserve) on every call. Only capacity changes.
template <class M, class T>
void reserve_growth(M& m, std::size_t vertices, std::size_t edges, std::size_t faces) {
    if constexpr (reservable_mesh<M, T> && edge_index_mesh<M, T>) {
        const std::size_t nv = T::vertex_index_bound(m), ne = T::edge_index_bound(m), nf = T::face_index_bound(m);
        if (8 * (vertices + edges + faces) >= nv + ne + nf) T::reserve(m, nv + vertices, ne + edges, nf + faces);
    }
    if constexpr (requires { T::reserve_journal(vertices, edges, faces); }) T::reserve_journal(vertices, edges, faces);
}

/// A set of element indices for selections, O(k) memory for k elements, so that selections
/// stay local (no array sized by the whole mesh). Sparse sets hash (open addressing, linear
/// probing, the table doubles at half load); a set whose indices are dense (the largest index
/// below 64 * 4 times the count, as when a whole mesh is selected) is a bitmap instead, which
/// keeps neighbouring indices in one cache line (hashed, a million-element selection misses
/// the cache on every lookup, which makes whole-mesh edits superlinear). Expected O(1) per insert
/// or lookup, amortised.
class index_set {
public:
    /// Adds i; returns whether it was new. Expected O(1), amortised.
    bool insert(std::size_t i) {
        if (dense_) {
            if (i / 64 >= bits_.size() && !grow_bits(i)) return insert(i);  // became sparse: hashed now
            const std::uint64_t bit = std::uint64_t{1} << (i % 64);
            if (bits_[i / 64] & bit) return false;
            bits_[i / 64] |= bit;
            ++size_;
            return true;
        }
        if (2 * (size_ + 1) > slots_.size()) {
            grow(i);
            if (dense_) return insert(i);
        }
        std::size_t s = slot(i);
        while (slots_[s] != empty) {
            if (slots_[s] == i) return false;
            s = (s + 1) & (slots_.size() - 1);
        }
        slots_[s] = i;
        ++size_;
        if (i > max_) max_ = i;
        return true;
    }
    /// Whether i was inserted. Expected O(1).
    bool contains(std::size_t i) const {
        if (dense_) return i / 64 < bits_.size() && (bits_[i / 64] >> (i % 64) & 1u);
        if (slots_.empty()) return false;
        for (std::size_t s = slot(i); slots_[s] != empty; s = (s + 1) & (slots_.size() - 1))
            if (slots_[s] == i) return true;
        return false;
    }
    /// Number of distinct indices inserted.
    std::size_t size() const { return size_; }

private:
    static constexpr std::size_t empty = ~std::size_t{0};
    // A bitmap may use up to this many 64-bit words per element (as much memory as the table).
    static constexpr std::size_t words_per_element = 4;
    std::size_t slot(std::size_t i) const {
        // Fibonacci hashing spreads consecutive indices over the table.
        return static_cast<std::size_t>((static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull) >> shift_);
    }
    /// Doubles the table, or turns it into a bitmap when the indices (with `next`) are dense.
    void grow(std::size_t next) {
        std::vector<std::size_t> old = std::move(slots_);
        const std::size_t top = std::max(max_, next);
        if (size_ >= 64 && top / 64 + 1 <= words_per_element * (size_ + 1)) {
            dense_ = true;
            bits_.assign(top / 64 + 1, 0);
            for (auto i : old)
                if (i != empty) bits_[i / 64] |= std::uint64_t{1} << (i % 64);
            return;
        }
        const std::size_t n = old.empty() ? 16 : 2 * old.size();
        slots_.assign(n, empty);
        shift_ = 64;
        for (std::size_t c = n; c > 1; c >>= 1) --shift_;
        size_ = 0;
        for (auto i : old)
            if (i != empty) insert(i);
    }
    /// Makes the bitmap reach index i if that keeps it dense (geometric growth); otherwise
    /// moves the set back into a hash table and returns false.
    bool grow_bits(std::size_t i) {
        const std::size_t need = i / 64 + 1, limit = words_per_element * (size_ + 1);
        if (need <= limit) {
            bits_.resize(std::max(need, std::min(2 * bits_.size(), limit)), 0);
            return true;
        }
        std::vector<std::uint64_t> old = std::move(bits_);
        bits_.clear();
        dense_ = false;
        std::size_t n = 16;
        while (n < 2 * (size_ + 1)) n *= 2;
        slots_.assign(2 * n, empty);
        shift_ = 64;
        for (std::size_t c = slots_.size(); c > 1; c >>= 1) --shift_;
        size_ = 0;
        for (std::size_t w = 0; w < old.size(); ++w)
            for (std::uint64_t b = old[w]; b != 0; b &= b - 1)
                insert(64 * w + static_cast<std::size_t>(std::countr_zero(b)));
        return false;
    }
    std::vector<std::size_t> slots_;
    std::vector<std::uint64_t> bits_;
    std::size_t size_ = 0, max_ = 0;
    unsigned shift_ = 64;
    bool dense_ = false;
};

/// A map from element indices to small values (positions in a local array), open addressing
/// like index_set: expected O(1) per operation, O(k) memory for k keys.
class index_map {
public:
    static constexpr std::size_t none = ~std::size_t{0};
    /// The value stored for i, or `none`. Expected O(1).
    std::size_t find(std::size_t i) const {
        if (keys_.empty()) return none;
        for (std::size_t s = slot(i); keys_[s] != none; s = (s + 1) & (keys_.size() - 1))
            if (keys_[s] == i) return values_[s];
        return none;
    }
    /// Stores value for i unless i is present; returns the value stored for i. Expected O(1).
    std::size_t emplace(std::size_t i, std::size_t value) {
        if (2 * (size_ + 1) > keys_.size()) grow();
        std::size_t s = slot(i);
        while (keys_[s] != none) {
            if (keys_[s] == i) return values_[s];
            s = (s + 1) & (keys_.size() - 1);
        }
        keys_[s] = i;
        values_[s] = value;
        ++size_;
        return value;
    }

private:
    std::size_t slot(std::size_t i) const {
        return static_cast<std::size_t>((static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull) >> shift_);
    }
    void grow() {
        std::vector<std::size_t> old_keys = std::move(keys_), old_values = std::move(values_);
        const std::size_t n = old_keys.empty() ? 16 : 2 * old_keys.size();
        keys_.assign(n, none);
        values_.assign(n, none);
        shift_ = 64;
        for (std::size_t c = n; c > 1; c >>= 1) --shift_;
        size_ = 0;
        for (std::size_t s = 0; s < old_keys.size(); ++s)
            if (old_keys[s] != none) emplace(old_keys[s], old_values[s]);
    }
    std::vector<std::size_t> keys_, values_;
    std::size_t size_ = 0;
    unsigned shift_ = 64;
};

/// The outgoing halfedges of v in rotation order (h -> next(opposite(h))), starting at the
/// stored one (a boundary halfedge when v is on the boundary), or an error if the links are
/// corrupt: a step reaches a halfedge that does not leave v, or the walk does not come back to
/// its start within as many steps as the mesh has halfedges (a cycle that misses the start).
/// A valid rotation visits each outgoing halfedge once, so no valid mesh is refused, however
/// high the degree. `what` names the calling function.
/// Cost O(V_adjacentV) on a valid mesh; on corrupt links at most O(H_all) steps and memory.
template <class M, class T>
result<std::vector<typename T::halfedge_handle>> checked_outgoing(const M& m, typename T::vertex_handle v,
                                                                  const char* what) {
    namespace de = detail::euler;
    std::vector<typename T::halfedge_handle> out;
    const auto start = T::vertex_halfedge(m, v);
    if (start == T::null_halfedge()) return out;
    const std::size_t bound = T::halfedge_index_bound(m);
    auto corrupt = [&](const std::string& why) {
        return fail(
            errc::topology,
            std::string(what) + ": the edges around " + de::name<M, T>("vertex", m, v) + " are corrupt (" + why + ")",
            de::index_of<M, T>(m, v));
    };
    auto h = start;
    do {
        if (T::target(m, T::opposite(m, h)) != v)
            return corrupt("halfedge " + std::to_string(T::halfedge_index(m, h)) +
                           " of its rotation does not leave it");
        if (out.size() >= bound)
            return corrupt("its rotation does not return to halfedge " + std::to_string(T::halfedge_index(m, start)) +
                           " within " + std::to_string(bound) + " steps");
        out.push_back(h);
        h = T::next(m, T::opposite(m, h));
    } while (h != start);
    return out;
}

/// The outgoing halfedges of v in rotation order, as checked_outgoing() gives them, for a
/// vertex already checked (check_corner_vertex(), which calls checked_outgoing()) whose links
/// only the edit itself has changed since. Unchecked: with corrupt links it stops after
/// H_all steps with a partial rotation, which its precondition excludes. O(V_adjacentV).
/// \pre checked_outgoing(m, v) succeeds.
template <class M, class T>
std::vector<typename T::halfedge_handle> outgoing(const M& m, typename T::vertex_handle v) {
    std::vector<typename T::halfedge_handle> out;
    const auto start = T::vertex_halfedge(m, v);
    if (start == T::null_halfedge()) return out;
    const std::size_t bound = T::halfedge_index_bound(m);
    auto h = start;
    do {
        out.push_back(h);
        h = T::next(m, T::opposite(m, h));
    } while (h != start && out.size() < bound);
    return out;
}

/// Checks that v can have its corner cut: it has edges, and at most one boundary gap (a
/// vertex with several gaps is non-manifold). `what` names the calling function.
template <class M, class T>
result<void> check_corner_vertex(const M& m, typename T::vertex_handle v, const char* what) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(m, v))
        return fail(errc::invalid_handle, std::string(what) + ": " + de::name<M, T>("vertex", m, v) + " does not exist",
                    de::index_of<M, T>(m, v));
    const auto rotation = checked_outgoing<M, T>(m, v, what);
    if (!rotation) return rotation.error();
    const auto& hs = rotation.value();
    if (hs.empty())
        return fail(
            errc::topology,
            std::string(what) + ": " + de::name<M, T>("vertex", m, v) + " is isolated; there is no corner to cut",
            de::index_of<M, T>(m, v));
    std::size_t gaps = 0;
    for (auto h : hs) gaps += T::face(m, h) == T::null_face() ? 1 : 0;
    if (gaps > 1)
        return fail(errc::non_manifold,
                    std::string(what) + ": " + de::name<M, T>("vertex", m, v) + " is non-manifold (" +
                        std::to_string(gaps) + " boundary gaps); its corner is not one cone",
                    de::index_of<M, T>(m, v));
    if (gaps == 1 && hs.size() < 2)
        return fail(errc::topology, std::string(what) + ": " + de::name<M, T>("vertex", m, v) + " ends a wire edge",
                    de::index_of<M, T>(m, v));
    if (gaps == 0 && hs.size() < 2)
        return fail(errc::topology, std::string(what) + ": " + de::name<M, T>("vertex", m, v) + " has degree 1",
                    de::index_of<M, T>(m, v));
    for (auto h : hs)
        if (T::target(m, h) == v)
            return fail(errc::topology, std::string(what) + ": " + de::name<M, T>("vertex", m, v) + " has a loop edge",
                        de::index_of<M, T>(m, v));
    return {};
}

/// Test hook for the fault-injection suites: traits that declare `static bool
/// fail_inner_call()` can make any inner operator call of an edit fail (as if its precondition
/// had not held) when it returns true. Absent on every real model: compiles to nothing.
template <class T>
result<void> inner_call_allowed(const char* what) {
    if constexpr (fault_injecting_traits<T>) {
        if (T::fail_inner_call())
            return fail(errc::topology, std::string(what) + ": failure injected by the traits (test hook)");
    }
    return {};
}

/// The Euler operators as an edit calls them: through inner_call_allowed, results passed on.
template <class M, class T>
result<make_edge_vertex_result<M, T>> mev(M& m, typename T::halfedge_handle corner, const vec3<double>& p) {
    if (auto ok = inner_call_allowed<T>("make_edge_vertex"); !ok) return ok.error();
    return make_edge_vertex<M, T>(m, corner, to_point<M, T>(p));
}
template <class M, class T>
result<make_edge_face_result<M, T>> mef(M& m, typename T::halfedge_handle a, typename T::halfedge_handle b) {
    if (auto ok = inner_call_allowed<T>("make_edge_face"); !ok) return ok.error();
    return make_edge_face<M, T>(m, a, b);
}
template <class M, class T>
result<void> kef(M& m, typename T::halfedge_handle h) {
    if (auto ok = inner_call_allowed<T>("kill_edge_face"); !ok) return ok.error();
    if (auto r = kill_edge_face<M, T>(m, h); !r) return r.error();
    return {};
}
template <class M, class T>
result<void> kev(M& m, typename T::halfedge_handle h) {
    if (auto ok = inner_call_allowed<T>("kill_edge_vertex"); !ok) return ok.error();
    if (auto r = kill_edge_vertex<M, T>(m, h); !r) return r.error();
    return {};
}

/// What split_edge made of the halfedge u -> w.
template <class M, class T>
struct split_result {
    typename T::vertex_handle vertex;           ///< the new vertex x
    typename T::halfedge_handle first, second;  ///< u -> x and x -> w, on the side of the split halfedge
};

/// Splits the edge of h (u -> w) at a new vertex placed at p, from Euler operators: makeEV
/// grows x from u inside face(h), makeEF joins x to w (cutting off the triangle u x w), and
/// killEF deletes the old edge, merging that triangle into the face on the other side.
/// V + 1, E + 1, F + 0. The old edge's handles die. O(1), plus O(V_adjacentV) on a boundary.
/// Precondition: h is a usable halfedge of an edge whose ends differ; an inner failure is
/// passed on (the caller's transaction undoes the partial split).
template <class M, class T>
result<split_result<M, T>> split_edge(M& m, typename T::halfedge_handle h, const vec3<double>& p) {
    const auto corner = T::prev(m, h);  // into u, in face(h)
    const auto o = T::opposite(m, h);
    const auto made_vertex = mev<M, T>(m, corner, p);  // loop: corner -> u->x -> x->u -> h
    if (!made_vertex) return made_vertex.error();
    const auto ux = made_vertex.value().halfedge;
    const auto made_face = mef<M, T>(m, ux, h);  // new face: h -> w->x -> x->u; old side: u->x -> x->w -> ...
    if (!made_face) return made_face.error();
    const auto xw = made_face.value().halfedge;
    if (auto ok = kef<M, T>(m, o); !ok) return ok.error();  // keeps face(o), kills the triangle (face of h)
    return split_result<M, T>{made_vertex.value().vertex, ux, xw};
}

/// Replaces vertex v by a polygon through its neighbours, from Euler operators: the corner of
/// every face around v is cut off by makeEF (a boundary gap is closed the same way, so that
/// its cut becomes the new face's one boundary edge), the triangles are merged by killEF on
/// the spokes, and the last spoke goes with v by killEV. Returns the new face, whose loop
/// runs through the neighbours in v's rotation order, consistently oriented with the faces
/// around. A vertex of degree 2 leaves no room for a face: it is dissolved instead (its two
/// neighbours joined by one edge, which both faces share) and the result is the null face.
///
/// Preconditions (checked by the callers): check_corner_vertex(v) holds; the neighbours are
/// distinct and no two of them are joined by an edge, except across a triangle at v. An inner
/// failure is passed on (the caller's transaction undoes the partial replacement).
/// V - 1, and for degree d: E + 0, F + 1 (d >= 3), or E - 1, F + 0 (d = 2).
/// Cost O(d): every face operation touches one triangle.
template <class M, class T>
result<typename T::face_handle> replace_vertex_by_polygon(M& m, typename T::vertex_handle v) {
    auto hs = outgoing<M, T>(m, v);
    const std::size_t d = hs.size();
    const bool boundary = T::face(m, hs[0]) == T::null_face();
    if (boundary) {
        // The gap lies between hs[d-1] and hs[0]; closing it makes the triangle a[d-1] v a[0].
        const auto into_last = T::prev(m, T::opposite(m, hs[d - 1]));
        if (auto r = mef<M, T>(m, into_last, hs[0]); !r) return r.error();
        if (d == 2) {
            // The one real face keeps the new edge as its boundary side.
            if (auto ok = kef<M, T>(m, T::opposite(m, hs[0])); !ok) return ok.error();
            if (auto ok = kev<M, T>(m, T::opposite(m, hs[1])); !ok) return ok.error();
            return T::null_face();
        }
    }
    // Cut the corner of each face around v into a triangle a[i] v a[i+1], unless it is one.
    for (std::size_t i = 0; i < d; ++i) {
        const auto in = T::opposite(m, hs[i]);            // a[i] -> v
        const auto out = hs[(i + 1) % d];                 // v -> a[i+1], same face as `in`
        if (T::next(m, T::next(m, out)) == in) continue;  // already a triangle
        if (auto r = mef<M, T>(m, T::prev(m, in), out); !r) return r.error();
        if (d == 2) break;  // one triangle, merged into the other face below
    }
    if (d == 2) {
        // hs[1]'s face is the triangle cut above; merge it into the face of hs[0].
        if (auto ok = kef<M, T>(m, hs[0]); !ok) return ok.error();
        if (auto ok = kev<M, T>(m, T::opposite(m, hs[1])); !ok) return ok.error();
        return T::null_face();
    }
    for (std::size_t i = 0; i + 1 < d; ++i)
        if (auto ok = kef<M, T>(m, hs[i]); !ok) return ok.error();
    const auto face = T::face(m, hs[0]);
    if (auto ok = kev<M, T>(m, T::opposite(m, hs[d - 1])); !ok) return ok.error();
    return face;
}

/// Newell normal of f (area-weighted, length = twice the area). O(face degree).
template <class M, class T>
vec3<double> face_area_vector(const M& m, typename T::face_handle f) {
    vec3<double> n{};
    const auto start = T::face_halfedge(m, f);
    auto h = start;
    do {
        n += newell_term(pos<M, T>(m, T::target(m, T::opposite(m, h))), pos<M, T>(m, T::target(m, h)));
        h = T::next(m, h);
    } while (h != start);
    return n;
}

inline bool finite(double x) { return std::isfinite(x); }

}  // namespace detail::editing
}  // namespace hmira
