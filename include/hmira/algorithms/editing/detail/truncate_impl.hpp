// hmira/algorithms/editing/detail/truncate_impl.hpp
// The machinery of truncate() (see truncate.hpp, which includes this file after its
// declarations): where each cut point goes, and the cuts and new faces built from the Euler
// operators. Not part of the public API.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "editing_common.hpp"

namespace hmira {

namespace detail::editing {

template <class M, class T>
result<void> check_truncate_options(const truncate_options& o, const char* what) {
    if (!(o.distance >= 0) || !finite(o.distance))
        return fail(errc::invalid_argument,
                    std::string(what) + ": distance must be finite and >= 0 (0 selects fraction)");
    if (o.distance == 0 && !(o.fraction > 0 && o.fraction < 1))
        return fail(errc::invalid_argument,
                    std::string(what) + ": fraction must lie in (0, 1), got " + std::to_string(o.fraction));
    return {};
}

/// Cut parameter along h (from its source), clamped as truncate_options says.
template <class M, class T>
double cut_parameter(const M& m, typename T::halfedge_handle h, const truncate_options& o, bool other_end_cut) {
    const double len = norm(pos<M, T>(m, T::target(m, h)) - pos<M, T>(m, detail::euler::source<M, T>(m, h)));
    double t = o.distance > 0 ? (len > 0 ? o.distance / len : 1.0) : o.fraction;
    const double limit = other_end_cut ? 0.5 : 1.0;
    return t < limit ? t : limit;
}

/// Truncates the vertices whose indices are in `selected` (already checked): splits every
/// edge at their cuts, then replaces each vertex by a polygon through its cut points. Run
/// inside a transaction (T journaled); an inner failure is passed on.
template <class M, class T, class Out>
result<void> truncate_checked(M& m, const std::vector<typename T::vertex_handle>& vs, const index_set& selected,
                              const truncate_options& o, Out& out) {
    using H = typename T::halfedge_handle;
    // Plan every split before changing anything, from the original geometry.
    struct cut {
        H h;
        double t_from, t_to;
        bool both;
    };
    std::vector<cut> cuts;
    for (auto v : vs)
        for (auto h : outgoing<M, T>(m, v)) {
            const auto w = T::target(m, h);
            const bool both = selected.contains(T::vertex_index(m, w));
            if (both && T::vertex_index(m, w) < T::vertex_index(m, v)) continue;  // planned from w
            const double tv = cut_parameter<M, T>(m, h, o, both);
            const double tw = both ? cut_parameter<M, T>(m, T::opposite(m, h), o, true) : 0.0;
            cuts.push_back({h, tv, tw, both});
        }
    // Each cut makes one or two points, each by split_edge (slots: V + 1, E + 2, F + 1); each
    // vertex of degree d then makes d edges and d faces (mef), one more on the boundary,
    // before merging them (kef).
    std::size_t points = 0, degrees = 0;
    for (const auto& c : cuts) {
        points += (c.both && c.t_from + c.t_to < 1.0) ? 2 : 1;
        degrees += c.both ? 2 : 1;
    }
    reserve_growth<M, T>(m, points, 2 * points + degrees, points + degrees + vs.size());
    progress_gate progress(o.progress, cuts.size() + vs.size(), "truncate");
    for (const auto& c : cuts) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto a = pos<M, T>(m, detail::euler::source<M, T>(m, c.h));
        const auto b = pos<M, T>(m, T::target(m, c.h));
        const auto s = split_edge<M, T>(m, c.h, lerp(a, b, c.t_from));
        if (!s) return s.error();
        out.vertices.push_back(s.value().vertex);
        if (!c.both || c.t_from + c.t_to >= 1.0) continue;  // meeting cuts share one point
        const auto s2 = split_edge<M, T>(m, s.value().second, lerp(a, b, 1.0 - c.t_to));
        if (!s2) return s2.error();
        out.vertices.push_back(s2.value().vertex);
    }
    for (auto v : vs) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto f = replace_vertex_by_polygon<M, T>(m, v);
        if (!f) return f.error();
        out.faces.push_back(f.value());
    }
    return {};
}

}  // namespace detail::editing

template <class M, class T, class R>
    requires truncatable_mesh<M, T> && range_of_handles<R, typename T::vertex_handle>
result<truncate_set_result<M, T>> truncate(M& mesh, const R& vertices, const truncate_options& options) {
    namespace de = detail::editing;
    if (auto ok = de::check_truncate_options<M, T>(options, "truncate"); !ok) return ok.error();
    std::vector<typename T::vertex_handle> vs;
    de::index_set selected;
    for (auto v0 : vertices) {
        const typename T::vertex_handle v = v0;
        if (auto ok = de::check_corner_vertex<M, T>(mesh, v, "truncate"); !ok) return ok.error();
        const auto i = T::vertex_index(mesh, v);
        if (selected.contains(i)) continue;
        selected.insert(i);
        vs.push_back(v);
    }
    return de::transact<M, T>(mesh, [&]<class JT>() -> result<truncate_set_result<M, T>> {
        truncate_set_result<M, T> out;
        if (auto ok = de::truncate_checked<M, JT>(mesh, vs, selected, options, out); !ok) return ok.error();
        return out;
    });
}

template <class M, class T>
    requires truncatable_mesh<M, T>
result<truncate_result<M, T>> truncate(M& mesh, typename T::vertex_handle vertex, const truncate_options& options) {
    namespace de = detail::editing;
    if (auto ok = de::check_truncate_options<M, T>(options, "truncate"); !ok) return ok.error();
    if (auto ok = de::check_corner_vertex<M, T>(mesh, vertex, "truncate"); !ok) return ok.error();
    de::index_set selected;
    selected.insert(T::vertex_index(mesh, vertex));
    auto r = de::transact<M, T>(mesh, [&]<class JT>() -> result<truncate_set_result<M, T>> {
        truncate_set_result<M, T> set;
        if (auto ok = de::truncate_checked<M, JT>(mesh, std::vector<typename T::vertex_handle>{vertex}, selected,
                                                  options, set);
            !ok)
            return ok.error();
        return set;
    });
    if (!r) return r.error();
    truncate_result<M, T> out{r.value().faces[0], {}};
    if (out.face != T::null_face()) {
        for (auto v : T::face_vertices(mesh, out.face)) out.vertices.push_back(v);
    } else {
        out.vertices = std::move(r.value().vertices);
    }
    return out;
}

template <class M, class T>
    requires truncatable_mesh<M, T>
result<truncate_set_result<M, T>> truncate_all(M& mesh, const truncate_options& options) {
    std::vector<typename T::vertex_handle> vs;
    for (auto v : T::vertices(mesh)) vs.push_back(v);
    return truncate<M, T>(mesh, vs, options);
}

}  // namespace hmira
