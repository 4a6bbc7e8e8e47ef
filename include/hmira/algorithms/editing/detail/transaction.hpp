// hmira/algorithms/editing/detail/transaction.hpp
// How truncate, bevel and extrude keep their "mesh unchanged on error" promise: the edit runs
// through a journaling traits class that records every raw mutation, and is rolled back from
// the journal when an inner operator fails or anything throws (std::bad_alloc). Not public API.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "../../../concepts.hpp"
#include "../../../core/result.hpp"
#include "../../../core/vec3.hpp"

namespace hmira::detail::editing {

// Why a journal and not "check everything first": an edit is a long chain of Euler operators
// whose later preconditions depend on what the earlier ones built (bevel's strips, grid fill's
// antennas), so checking them all up front would mean simulating the edit; and no up-front
// check can give the strong guarantee when an allocation throws half way. A journal covers
// both at O(1) time and memory per raw mutation, and keeps the edit local.
//
// What is journaled: set_next (with the stored prev of the new next, which set_next also
// overwrites on every shipped model), set_target, set_face, set_vertex_halfedge,
// set_face_halfedge, set_position, add/remove_inner_ring, and the elements created. Erasures
// are deferred to the commit, so a rollback never has to revive an element: after a rollback
// the same elements are live with the same handles, connectivity and positions; only index
// bounds and garbage (the created elements, erased again) differ. Requirement on the model:
// prev() reads a stored link in O(1) (true of every shipped model), and erase_* and setters do
// not allocate once an erasure has happened (OpenMesh's status bits are requested before the
// first change, through the traits' optional prepare_erase()).
//
// Elements made by the edit itself need no undo (the rollback erases them): a change to an
// element whose index is at or above the index bound the mesh had when the edit began is not
// journaled. That keeps a whole-mesh edit's journal to the changes of the old elements (a
// third of the entries for truncate_all), and its memory in proportion.

/// Makes room for one more element of v, growing geometrically: reserve(size() + 1) alone
/// reallocates on every call (libstdc++ reserves exactly), so a journal of n entries would
/// cost O(n^2). Amortised O(1).
template <class X>
void reserve_one_more(std::vector<X>& v) {
    if (v.size() == v.capacity()) v.reserve(std::max<std::size_t>(16, 2 * v.capacity()));
}

/// An append-only list in chunks that double up to 64k elements: unlike a vector it never
/// copies what it holds, so a journal of tens of millions of entries (a whole-mesh edit) needs
/// no transient 3x of its size, whose fresh pages would make such edits superlinear.
/// Amortised O(1).
template <class X>
class chunked_log {
public:
    void push_back(const X& x) {
        if (chunks_.empty() || chunks_.back().size() == chunks_.back().capacity()) {
            std::vector<X> c;
            c.reserve(chunks_.empty() ? 16
                                      : std::min<std::size_t>(2 * chunks_.back().capacity(), std::size_t{1} << 16));
            chunks_.push_back(std::move(c));
        }
        chunks_.back().push_back(x);
        ++size_;
    }
    std::size_t size() const { return size_; }
    /// Calls f on every element, newest first.
    template <class F>
    void for_each_newest_first(F&& f) const {
        for (auto c = chunks_.rbegin(); c != chunks_.rend(); ++c)
            for (auto it = c->rbegin(); it != c->rend(); ++it) f(*it);
    }

private:
    std::vector<std::vector<X>> chunks_;
    std::size_t size_ = 0;
};

/// Every raw mutation of one edit, in order, and what undoes it.
template <class M, class T>
class journal {
public:
    using H = typename T::halfedge_handle;
    using V = typename T::vertex_handle;
    using F = typename T::face_handle;
    using E = typename T::edge_handle;
    using P = vec3<typename T::scalar>;

    enum class kind : std::uint8_t {
        next,
        target,
        face,
        vertex_halfedge,
        face_halfedge,
        position,
        ring_added,
        ring_removed
    };
    struct entry {
        kind what;
        H h{};  // the halfedge changed (next, target, face), or the ring's halfedge
        H old_h{};
        V v{};
        F f{};  // (kind::position: the old position is the next one of positions_, newest first)
    };
    struct old_prev {
        H x, prev;
        std::size_t seq;
    };

    /// Remembers the index bounds: elements at or above them are made by the edit.
    explicit journal(const M& m)
        : halfedge_bound_(T::halfedge_index_bound(m)),
          vertex_bound_(T::vertex_index_bound(m)),
          face_bound_(T::face_index_bound(m)) {}

    void record_next(const M& m, H h, H n) {
        if (old(m, n)) {
            reserve_one_more(prev_);
            if (old(m, h)) entries_.push_back({kind::next, h, T::next(m, h), V{}, F{}});
            prev_.push_back({n, T::prev(m, n), prev_.size()});
        } else if (old(m, h)) {
            entries_.push_back({kind::next, h, T::next(m, h), V{}, F{}});
        }
    }
    void record_target(const M& m, H h) {
        if (old(m, h)) entries_.push_back({kind::target, h, H{}, T::target(m, h), F{}});
    }
    void record_face(const M& m, H h) {
        if (old(m, h)) entries_.push_back({kind::face, h, H{}, V{}, T::face(m, h)});
    }
    void record_vertex_halfedge(const M& m, V v) {
        if (!old(m, v)) return;
        // A model whose vertex_halfedge is derived from what it stores (CGAL keeps an incoming
        // halfedge) offers the stored value as is; the rollback writes that back.
        if constexpr (vertex_halfedge_restorable_mesh<M, T>)
            entries_.push_back({kind::vertex_halfedge, H{}, T::stored_vertex_halfedge(m, v), v, F{}});
        else
            entries_.push_back({kind::vertex_halfedge, H{}, T::vertex_halfedge(m, v), v, F{}});
    }
    void record_face_halfedge(const M& m, F f) {
        if (old(m, f)) entries_.push_back({kind::face_halfedge, H{}, T::face_halfedge(m, f), V{}, f});
    }
    void record_position(const M& m, V v) {
        if (!old(m, v)) return;
        reserve_one_more(positions_);
        entries_.push_back({kind::position, H{}, H{}, v, F{}});
        positions_.push_back(T::position(m, v));
    }
    void record_ring(F f, H h, bool added) {
        entries_.push_back({added ? kind::ring_added : kind::ring_removed, h, H{}, V{}, f});
    }

    /// Room for one more created element, reserved before the model creates it (so that
    /// recording it cannot throw after it exists).
    void reserve_created() {
        reserve_one_more(made_vertices_);
        reserve_one_more(made_edges_);
        reserve_one_more(made_faces_);
    }
    /// Room for that many more created elements (the edit's estimate; more still fit).
    void reserve_created(std::size_t vertices, std::size_t edges, std::size_t faces) {
        made_vertices_.reserve(made_vertices_.size() + vertices);
        made_edges_.reserve(made_edges_.size() + edges);
        made_faces_.reserve(made_faces_.size() + faces);
        erase_edges_.reserve(erase_edges_.size() + edges);  // the edits kill about as many as they make
        erase_faces_.reserve(erase_faces_.size() + faces);
    }
    void created(V v) { made_vertices_.push_back(v); }
    void created(E e) { made_edges_.push_back(e); }
    void created(F f) { made_faces_.push_back(f); }
    void erase_later(E e) { erase_edges_.push_back(e); }
    void erase_later(F f) { erase_faces_.push_back(f); }
    void erase_later(V v) { erase_vertices_.push_back(v); }

    /// Number of raw mutations so far (the fault-injection tests count them).
    std::size_t size() const {
        return entries_.size() + made_vertices_.size() + made_edges_.size() + made_faces_.size();
    }

    /// Performs the deferred erasures. Erasing only marks elements on every shipped model and
    /// cannot fail; should the very first one throw, nothing has happened yet and the caller
    /// rolls back.
    void commit(M& m) {
        for (auto e : erase_edges_) T::erase_edge(m, e);
        for (auto f : erase_faces_) T::erase_face(m, f);
        for (auto v : erase_vertices_) T::erase_vertex(m, v);
    }

    /// Undoes everything recorded, newest first; then re-links the stored prev of every
    /// halfedge that set_next reached, and erases the created elements. Allocates nothing.
    void rollback(M& m) noexcept {
        std::size_t position = positions_.size();
        entries_.for_each_newest_first([&](const entry& e) {
            const entry* it = &e;
            switch (it->what) {
                case kind::next:
                    // A new halfedge had no next yet; it is erased below.
                    if (it->old_h != T::null_halfedge()) T::set_next(m, it->h, it->old_h);
                    break;
                case kind::target: T::set_target(m, it->h, it->v); break;
                case kind::face: T::set_face(m, it->h, it->f); break;
                case kind::vertex_halfedge:
                    if constexpr (vertex_halfedge_restorable_mesh<M, T>)
                        T::restore_vertex_halfedge(m, it->v, it->old_h);
                    else
                        T::set_vertex_halfedge(m, it->v, it->old_h);
                    break;
                case kind::face_halfedge: T::set_face_halfedge(m, it->f, it->old_h); break;
                case kind::position:
                    --position;
                    if constexpr (position_mutable_mesh<M, T>) T::set_position(m, it->v, positions_[position]);
                    break;
                case kind::ring_added:
                    if constexpr (inner_ring_mutable_mesh<M, T>) T::remove_inner_ring(m, it->f, it->h);
                    break;
                case kind::ring_removed:
                    if constexpr (inner_ring_mutable_mesh<M, T>) T::add_inner_ring(m, it->f, it->h);
                    break;
            }
        });
        // set_next(h, n) also set prev(n) = h. The first recorded prev of each n is its value
        // before the edit; set_next(prev, n) restores it (and sets next(prev) = n, its old value).
        std::sort(made_edges_.begin(), made_edges_.end(),
                  [&](E a, E b) { return T::edge_index(m, a) < T::edge_index(m, b); });
        auto made = [&](H h) {
            const auto e = T::edge(m, h);
            return std::binary_search(made_edges_.begin(), made_edges_.end(), e,
                                      [&](E a, E b) { return T::edge_index(m, a) < T::edge_index(m, b); });
        };
        std::sort(prev_.begin(), prev_.end(), [&](const old_prev& a, const old_prev& b) {
            const auto ia = T::halfedge_index(m, a.x), ib = T::halfedge_index(m, b.x);
            return ia != ib ? ia < ib : a.seq < b.seq;
        });
        for (std::size_t i = 0; i < prev_.size(); ++i) {
            if (i > 0 && prev_[i].x == prev_[i - 1].x) continue;
            const auto& r = prev_[i];
            if (r.prev == T::null_halfedge() || made(r.x) || made(r.prev)) continue;
            T::set_next(m, r.prev, r.x);
        }
        for (auto e : made_edges_) T::erase_edge(m, e);
        for (auto f : made_faces_) T::erase_face(m, f);
        for (auto v : made_vertices_) T::erase_vertex(m, v);
    }

private:
    // Whether x existed when the edit began (a reused slot counts as old: journaled, harmless).
    bool old(const M& m, H h) const { return T::halfedge_index(m, h) < halfedge_bound_; }
    bool old(const M& m, V v) const { return T::vertex_index(m, v) < vertex_bound_; }
    bool old(const M& m, F f) const { return T::face_index(m, f) < face_bound_; }

    std::size_t halfedge_bound_, vertex_bound_, face_bound_;
    chunked_log<entry> entries_;
    std::vector<old_prev> prev_;
    std::vector<P> positions_;
    std::vector<V> made_vertices_;
    std::vector<E> made_edges_;
    std::vector<F> made_faces_;
    std::vector<E> erase_edges_;
    std::vector<F> erase_faces_;
    std::vector<V> erase_vertices_;
};

/// T with every raw mutation recorded in the active journal; navigation is T's own. An edit
/// instantiated with these traits can be rolled back. The journal is per thread, so edits on
/// different meshes may run in parallel threads.
template <class M, class T>
struct journaled_traits : T {
    using H = typename T::halfedge_handle;
    using V = typename T::vertex_handle;
    using F = typename T::face_handle;
    using E = typename T::edge_handle;
    static inline thread_local journal<M, T>* active = nullptr;

    static void set_next(M& m, H h, H n) {
        active->record_next(m, h, n);
        T::set_next(m, h, n);
    }
    static void set_target(M& m, H h, V v) {
        active->record_target(m, h);
        T::set_target(m, h, v);
    }
    static void set_face(M& m, H h, F f) {
        active->record_face(m, h);
        T::set_face(m, h, f);
    }
    static void set_vertex_halfedge(M& m, V v, H h) {
        active->record_vertex_halfedge(m, v);
        T::set_vertex_halfedge(m, v, h);
    }
    static void set_face_halfedge(M& m, F f, H h) {
        active->record_face_halfedge(m, f);
        T::set_face_halfedge(m, f, h);
    }
    static void set_position(M& m, V v, const vec3<typename T::scalar>& p)
        requires position_mutable_mesh<M, T>
    {
        active->record_position(m, v);
        T::set_position(m, v, p);
    }
    static void add_inner_ring(M& m, F f, H h)
        requires inner_ring_mutable_mesh<M, T>
    {
        active->record_ring(f, h, true);
        T::add_inner_ring(m, f, h);
    }
    static void remove_inner_ring(M& m, F f, H h)
        requires inner_ring_mutable_mesh<M, T>
    {
        active->record_ring(f, h, false);
        T::remove_inner_ring(m, f, h);
    }
    /// Journal room for an edit that creates that many elements (see reserve_growth).
    static void reserve_journal(std::size_t vertices, std::size_t edges, std::size_t faces) {
        active->reserve_created(vertices, edges, faces);
    }
    static H new_edge(M& m, V a, V b) {
        active->reserve_created();
        const H h = T::new_edge(m, a, b);
        active->created(T::edge(m, h));
        return h;
    }
    static F new_face(M& m) {
        active->reserve_created();
        const F f = T::new_face(m);
        active->created(f);
        return f;
    }
    static V add_vertex(M& m, const vec3<typename T::scalar>& p) {
        active->reserve_created();
        const V v = T::add_vertex(m, p);
        active->created(v);
        return v;
    }
    static void erase_edge(M&, E e) { active->erase_later(e); }
    static void erase_face(M&, F f) { active->erase_later(f); }
    static void erase_vertex(M&, V v) { active->erase_later(v); }
};

/// Runs `body.template operator()<JT>()` with JT = journaled_traits<M, T>: it must do all its
/// mutation through JT. On an error result, or on any exception, every change is undone (the
/// exception is rethrown); otherwise the deferred erasures are applied. Returns body's result.
/// Cost: O(1) time and memory per raw mutation on top of the edit.
template <class M, class T, class Body>
auto transact(M& m, Body&& body) -> decltype(body.template operator()<journaled_traits<M, T>>()) {
    using JT = journaled_traits<M, T>;
    if constexpr (erase_preparing_mesh<M, T>) T::prepare_erase(m);
    journal<M, T> j(m);
    struct activation {
        journal<M, T>* saved;
        explicit activation(journal<M, T>* now) : saved(JT::active) { JT::active = now; }
        ~activation() { JT::active = saved; }
        activation(const activation&) = delete;
        activation& operator=(const activation&) = delete;
    };
    try {
        auto r = [&] {
            activation on(&j);
            return body.template operator()<JT>();
        }();
        if (!r) {
            j.rollback(m);
            return r;
        }
        j.commit(m);
        return r;
    } catch (...) {
        j.rollback(m);
        throw;
    }
}

}  // namespace hmira::detail::editing
