// hmira/algorithms/triangle/detail/split_links.hpp
// The link changes of an edge split, without its checks: split_edge's core, and what Loop
// subdivision calls for a whole batch of edges it checked up front.
#pragma once

#include "../triangle_common.hpp"

namespace hmira {

namespace detail::triangle_ops {

/// Makes new edges and faces through the traits (what split_links uses unless told otherwise).
template <class M, class T>
struct traits_new_elements {
    M& mesh;
    typename T::halfedge_handle edge(typename T::vertex_handle a, typename T::vertex_handle b) {
        return T::new_edge(mesh, a, b);
    }
    typename T::face_handle face() { return T::new_face(mesh); }
};

/// The link changes of split_edge, without its checks, at an isolated vertex w the caller
/// made: for callers that established the preconditions for a whole batch of edges up front
/// (Loop subdivision). `cut_h` / `cut_o`: split the triangle on that side. New edges and
/// faces come from `make.edge(a, b)` (as T::new_edge) and `make.face()` (as T::new_face),
/// which lets a batch take them from elements it made in bulk. Returns the new halfedge
/// w -> b. O(1).
template <class M, class T, class Make>
typename T::halfedge_handle split_links(M& mesh, typename T::halfedge_handle h, typename T::vertex_handle w, bool cut_h,
                                        bool cut_o, Make& make) {
    const auto o = T::opposite(mesh, h);
    const auto a = T::target(mesh, o), b = T::target(mesh, h);
    const auto f0 = T::face(mesh, h), f1 = T::face(mesh, o);
    const auto hn = T::next(mesh, h), op = T::prev(mesh, o);
    const auto a_out = T::vertex_halfedge(mesh, a);
    const auto b_out = T::vertex_halfedge(mesh, b);

    const auto h2 = make.edge(w, b);        // w -> b
    const auto o2 = T::opposite(mesh, h2);  // b -> w
    // h: a -> w, o: w -> a; the new edge takes h's place in front of hn and o's behind op.
    T::set_target(mesh, h, w);
    T::set_next(mesh, h, h2);
    T::set_next(mesh, h2, hn);
    T::set_face(mesh, h2, f0);
    T::set_next(mesh, op, o2);
    T::set_next(mesh, o2, o);
    T::set_face(mesh, o2, f1);

    if (cut_h) {  // (a, w, b, c) -> (a, w, c) + (w, b, c)
        const auto c = T::target(mesh, hn);
        const auto hp = T::prev(mesh, h);
        const auto wc = make.edge(w, c);
        const auto cw = T::opposite(mesh, wc);
        const auto g = make.face();
        T::set_next(mesh, h, wc);
        T::set_next(mesh, wc, hp);
        T::set_face(mesh, wc, f0);
        T::set_next(mesh, hn, cw);
        T::set_next(mesh, cw, h2);
        T::set_face(mesh, cw, g);
        T::set_face(mesh, h2, g);
        T::set_face(mesh, hn, g);
        T::set_face_halfedge(mesh, f0, h);
        T::set_face_halfedge(mesh, g, h2);
    }
    if (cut_o) {  // (w, a, d, b) -> (w, a, d) + (b, w, d)
        const auto on = T::next(mesh, o);
        const auto d = T::target(mesh, on);
        const auto dw = make.edge(d, w);
        const auto wd = T::opposite(mesh, dw);
        const auto g = make.face();
        T::set_next(mesh, on, dw);
        T::set_next(mesh, dw, o);
        T::set_face(mesh, dw, f1);
        T::set_next(mesh, o2, wd);
        T::set_next(mesh, wd, op);
        T::set_face(mesh, wd, g);
        T::set_face(mesh, o2, g);
        T::set_face(mesh, op, g);
        T::set_face_halfedge(mesh, f1, o);
        T::set_face_halfedge(mesh, g, o2);
    }
    // w sits on the boundary exactly when the edge did; b's stored o (b -> a) now leaves w.
    T::set_vertex_halfedge(mesh, w, f0 == T::null_face() ? h2 : o);
    T::set_vertex_halfedge(mesh, b, b_out == o ? o2 : b_out);
    T::set_vertex_halfedge(mesh, a, a_out);
    return h2;
}

/// split_links with new edges and faces from the traits.
template <class M, class T>
typename T::halfedge_handle split_links(M& mesh, typename T::halfedge_handle h, typename T::vertex_handle w, bool cut_h,
                                        bool cut_o) {
    traits_new_elements<M, T> make{mesh};
    return split_links<M, T>(mesh, h, w, cut_h, cut_o, make);
}

}  // namespace detail::triangle_ops

}  // namespace hmira
