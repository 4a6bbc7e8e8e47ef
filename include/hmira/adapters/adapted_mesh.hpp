// hmira/adapters/adapted_mesh.hpp
// Composes adapters with a mesh: adapted_mesh<Mesh, Traits, Adapters...> refers to the user's
// mesh (no copy) and its mesh_traits present everything the mesh has plus what the adapters
// synthesise, so an algorithm that needs vertex_adjacency_mesh runs on face_vertex_mesh.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>

#include "../concepts.hpp"
#include "edge_list.hpp"
#include "face_adjacency.hpp"
#include "vertex_adjacency.hpp"
#include "vertex_edge_adjacency.hpp"
#include "vertex_face_adjacency.hpp"

namespace hmira {

namespace detail {

// One tag per operation an adapter may provide; `test` says whether adapter A provides it.
struct op_adjacent_vertices {
    template <class A, class M, class T>
    static constexpr bool test =
        requires(const A& a, const M& m, typename T::vertex_handle v) { a.adjacent_vertices(m, v); };
};
struct op_vertex_faces {
    template <class A, class M, class T>
    static constexpr bool test =
        requires(const A& a, const M& m, typename T::vertex_handle v) { a.vertex_faces(m, v); };
};
struct op_vertex_edges {
    template <class A, class M, class T>
    static constexpr bool test =
        requires(const A& a, const M& m, typename T::vertex_handle v) { a.vertex_edges(m, v); };
};
struct op_adjacent_faces {
    template <class A, class M, class T>
    static constexpr bool test =
        requires(const A& a, const M& m, typename T::face_handle f) { a.adjacent_faces(m, f); };
};
struct op_edges {
    template <class A, class M, class T>
    static constexpr bool test = requires(const A& a, const M& m) {
        a.edges(m);
        a.edge_count(m);
    };
};
struct op_reverse_face {
    template <class A, class M, class T>
    static constexpr bool test = requires(A& a, M& m, typename T::face_handle f) { a.reverse_face(m, f); };
};

inline constexpr std::size_t no_provider = static_cast<std::size_t>(-1);

/// Index of the first adapter that provides Op, or no_provider.
template <class Op, class M, class T, class... As>
constexpr std::size_t first_provider() {
    constexpr std::array<bool, sizeof...(As) + 1> provides{Op::template test<As, M, T>..., false};
    for (std::size_t i = 0; i < sizeof...(As); ++i)
        if (provides[i]) return i;
    return no_provider;
}

template <class... As>
struct first_edge_handle {};
template <class A, class... As>
    requires requires { typename A::edge_handle; }
struct first_edge_handle<A, As...> {
    using type = typename A::edge_handle;
};
template <class A, class... As>
struct first_edge_handle<A, As...> : first_edge_handle<As...> {};

/// The edge handle type: the adapters' if any adapter names one, else the mesh's own if any.
template <class B, class... As>
struct adapted_edge_types {};
template <class B, class... As>
    requires requires { typename first_edge_handle<As...>::type; }
struct adapted_edge_types<B, As...> {
    using edge_handle = typename first_edge_handle<As...>::type;
};
template <class B, class... As>
    requires(
        !requires { typename first_edge_handle<As...>::type; } && requires { typename B::edge_handle; })
struct adapted_edge_types<B, As...> {
    using edge_handle = typename B::edge_handle;
};

}  // namespace detail

/// A mesh seen through adapters. Holds a pointer to the user's mesh (which must outlive it)
/// and the adapters' state (the indexes of indexed_* adapters). Copying an adapted_mesh
/// copies the indexes; moving it moves them.
///
/// An adapter's operation takes precedence over the mesh's own, so that a test or a user can
/// force one flavour; what no adapter provides is forwarded to BaseTraits. Mutations are
/// forwarded too; indexed adapters then report the change (hmira_error) until refresh().
template <class Mesh, class BaseTraits, class... Adapters>
class adapted_mesh {
public:
    /// The user's mesh type, without const.
    using base_mesh = std::remove_const_t<Mesh>;
    /// The traits that serve whatever no adapter provides.
    using base_traits = BaseTraits;

    /// Builds every adapter from the mesh (indexed ones build their index: O(C log C)).
    explicit adapted_mesh(Mesh& m) : mesh_(&m), adapters_(Adapters(std::as_const(m))...) {}
    /// Takes adapters built by the caller (for adapters that need arguments).
    adapted_mesh(Mesh& m, Adapters... adapters)
        requires(sizeof...(Adapters) > 0)
        : mesh_(&m), adapters_(std::move(adapters)...) {}

    /// The user's mesh this adapted_mesh refers to. O(1).
    ///@{
    Mesh& base() noexcept { return *mesh_; }
    const base_mesh& base() const noexcept { return *mesh_; }
    ///@}

    /// Rebuilds the indexed adapters from the mesh as it is now; views returned before dangle.
    void refresh() {
        std::apply([this](auto&... a) { (a.refresh(std::as_const(*mesh_)), ...); }, adapters_);
    }

    /// The held adapter of type A (ill-formed unless A occurs exactly once in Adapters). O(1).
    ///@{
    template <class A>
    const A& adapter() const {
        return std::get<A>(adapters_);
    }
    template <class A>
    A& adapter() {
        return std::get<A>(adapters_);
    }
    ///@}

    /// Position in Adapters of the first adapter that provides operation Op (a detail::op_*
    /// tag), or detail::no_provider when none does and the base traits serve it.
    template <class Op>
    static constexpr std::size_t provider = detail::first_provider<Op, base_mesh, BaseTraits, Adapters...>();
    /// Whether some adapter provides operation Op.
    template <class Op>
    static constexpr bool provides = provider<Op> != detail::no_provider;
    /// The adapter that provides operation Op. Precondition: `provides<Op>`. O(1).
    ///@{
    template <class Op>
    const auto& provider_of() const {
        return std::get<provider<Op>>(adapters_);
    }
    template <class Op>
    auto& provider_of() {
        return std::get<provider<Op>>(adapters_);
    }
    ///@}

private:
    Mesh* mesh_;
    std::tuple<Adapters...> adapters_;
};

/// The traits of an adapted mesh: the base traits' operations and the adapters' ones.
/// Queries on a temporary adapted_mesh are deleted: their views would outlive its index.
template <class Mesh, class B, class... As>
struct mesh_traits<adapted_mesh<Mesh, B, As...>> : detail::adapted_edge_types<B, As...> {
    using W = adapted_mesh<Mesh, B, As...>;
    using M = std::remove_const_t<Mesh>;
    using vertex_handle = typename B::vertex_handle;
    using face_handle = typename B::face_handle;
    using scalar = typename B::scalar;
    static constexpr bool adapter_edges = requires { typename detail::first_edge_handle<As...>::type; };

    // ----- forwarded from the mesh ---------------------------------------------------------------
    static auto vertices(const W& w) { return B::vertices(w.base()); }
    static auto faces(const W& w) { return B::faces(w.base()); }
    static std::size_t vertex_count(const W& w) { return B::vertex_count(w.base()); }
    static std::size_t face_count(const W& w) { return B::face_count(w.base()); }
    static std::size_t vertex_index(const W& w, vertex_handle v)
        requires vertex_index_mesh<M, B>
    {
        return B::vertex_index(w.base(), v);
    }
    static std::size_t vertex_index_bound(const W& w)
        requires vertex_index_mesh<M, B>
    {
        return B::vertex_index_bound(w.base());
    }
    static std::size_t face_index(const W& w, face_handle f)
        requires face_index_mesh<M, B>
    {
        return B::face_index(w.base(), f);
    }
    static std::size_t face_index_bound(const W& w)
        requires face_index_mesh<M, B>
    {
        return B::face_index_bound(w.base());
    }
    static auto face_vertices(const W& w, face_handle f)
        requires face_vertex_range_mesh<M, B>
    {
        return B::face_vertices(w.base(), f);
    }
    static void face_vertices(const W&&, face_handle) = delete;
    static decltype(auto) position(const W& w, vertex_handle v)
        requires positioned_mesh<M, B>
    {
        return B::position(w.base(), v);
    }
    static void set_position(W& w, vertex_handle v, const vec3<scalar>& p)
        requires position_mutable_mesh<M, B>
    {
        B::set_position(w.base(), v, p);
    }
    static vertex_handle add_vertex(W& w, const vec3<scalar>& p)
        requires mesh_builder<M, B>
    {
        return B::add_vertex(w.base(), p);
    }
    static result<face_handle> add_face(W& w, std::span<const vertex_handle> vs)
        requires mesh_builder<M, B>
    {
        return B::add_face(w.base(), vs);
    }
    static auto change_count(const W& w)
        requires change_counted_mesh<M, B>
    {
        return B::change_count(w.base());
    }

    static void reverse_face(W& w, face_handle f)
        requires(W::template provides<detail::op_reverse_face> || face_reversible_mesh<M, B>)
    {
        if constexpr (W::template provides<detail::op_reverse_face>)
            w.template provider_of<detail::op_reverse_face>().reverse_face(w.base(), f);
        else
            B::reverse_face(w.base(), f);
    }

    // ----- adapted, or forwarded when no adapter provides them ------------------------------------
    static decltype(auto) adjacent_vertices(const W& w, vertex_handle v)
        requires(W::template provides<detail::op_adjacent_vertices> || vertex_adjacency_mesh<M, B>)
    {
        if constexpr (W::template provides<detail::op_adjacent_vertices>)
            return w.template provider_of<detail::op_adjacent_vertices>().adjacent_vertices(w.base(), v);
        else
            return B::adjacent_vertices(w.base(), v);
    }
    static void adjacent_vertices(const W&&, vertex_handle) = delete;

    static decltype(auto) vertex_faces(const W& w, vertex_handle v)
        requires(W::template provides<detail::op_vertex_faces> || vertex_face_adjacency_mesh<M, B>)
    {
        if constexpr (W::template provides<detail::op_vertex_faces>)
            return w.template provider_of<detail::op_vertex_faces>().vertex_faces(w.base(), v);
        else
            return B::vertex_faces(w.base(), v);
    }
    static void vertex_faces(const W&&, vertex_handle) = delete;

    static decltype(auto) adjacent_faces(const W& w, face_handle f)
        requires(W::template provides<detail::op_adjacent_faces> || face_adjacency_mesh<M, B>)
    {
        if constexpr (W::template provides<detail::op_adjacent_faces>)
            return w.template provider_of<detail::op_adjacent_faces>().adjacent_faces(w.base(), f);
        else
            return B::adjacent_faces(w.base(), f);
    }
    static void adjacent_faces(const W&&, face_handle) = delete;

    // Edges come all from the adapters or all from the mesh, so that handles never mix.
    static decltype(auto) vertex_edges(const W& w, vertex_handle v)
        requires(W::template provides<detail::op_vertex_edges> || (!adapter_edges && vertex_edge_adjacency_mesh<M, B>))
    {
        if constexpr (W::template provides<detail::op_vertex_edges>)
            return w.template provider_of<detail::op_vertex_edges>().vertex_edges(w.base(), v);
        else
            return B::vertex_edges(w.base(), v);
    }
    static void vertex_edges(const W&&, vertex_handle) = delete;

    static decltype(auto) edges(const W& w)
        requires(W::template provides<detail::op_edges> || (!adapter_edges && edge_list_mesh<M, B>))
    {
        if constexpr (W::template provides<detail::op_edges>)
            return w.template provider_of<detail::op_edges>().edges(w.base());
        else
            return B::edges(w.base());
    }
    static void edges(const W&&) = delete;
    static std::size_t edge_count(const W& w)
        requires(W::template provides<detail::op_edges> || (!adapter_edges && edge_list_mesh<M, B>))
    {
        if constexpr (W::template provides<detail::op_edges>)
            return w.template provider_of<detail::op_edges>().edge_count(w.base());
        else
            return B::edge_count(w.base());
    }
    template <class E>
    static auto edge_vertices(const W& w, E e)
        requires(W::template provides<detail::op_edges> || (!adapter_edges && edge_list_mesh<M, B>))
    {
        if constexpr (W::template provides<detail::op_edges>)
            return w.template provider_of<detail::op_edges>().edge_vertices(w.base(), e);
        else
            return B::edge_vertices(w.base(), e);
    }
};

/// Every adjacency of thesis table 4.3 by brute force: no memory, O(F_all) per query.
template <class Mesh, class T = default_traits<Mesh>>
using with_brute_force_adjacency = adapted_mesh<Mesh, T, brute_force_vertex_adjacency<std::remove_const_t<Mesh>, T>,
                                                brute_force_vertex_face_adjacency<std::remove_const_t<Mesh>, T>,
                                                brute_force_vertex_edge_adjacency<std::remove_const_t<Mesh>, T>,
                                                brute_force_face_adjacency<std::remove_const_t<Mesh>, T>,
                                                brute_force_edge_list<std::remove_const_t<Mesh>, T>>;

/// Every adjacency of thesis table 4.3 from indexes built once in O(C log C), then at the
/// thesis's efficient cost per query; stale use throws hmira_error.
template <class Mesh, class T = default_traits<Mesh>>
using with_indexed_adjacency =
    adapted_mesh<Mesh, T, indexed_vertex_adjacency<std::remove_const_t<Mesh>, T>,
                 indexed_vertex_face_adjacency<std::remove_const_t<Mesh>, T>,
                 indexed_vertex_edge_adjacency<std::remove_const_t<Mesh>, T>,
                 indexed_face_adjacency<std::remove_const_t<Mesh>, T>, indexed_edge_list<std::remove_const_t<Mesh>, T>>;

/// The documented default flavour is indexed: an algorithm that asks every vertex for its
/// neighbours costs O(C log C) once instead of O(V_all x F_all). Choose brute force when the
/// mesh is queried a handful of times and memory matters more.
template <class Mesh, class T = default_traits<Mesh>>
using with_adjacency = with_indexed_adjacency<Mesh, T>;

/// `auto a = hmira::adapt_brute_force(mesh); algorithm(a);` (the mesh must outlive `a`).
template <class Mesh, class T = default_traits<Mesh>>
    requires adapter_source_mesh<std::remove_const_t<Mesh>, T>
with_brute_force_adjacency<Mesh, T> adapt_brute_force(Mesh& mesh) {
    return with_brute_force_adjacency<Mesh, T>(mesh);
}

/// `auto a = hmira::adapt_indexed(mesh); algorithm(a);` Builds the indexes now, O(C log C).
template <class Mesh, class T = default_traits<Mesh>>
    requires indexed_adapter_source_mesh<std::remove_const_t<Mesh>, T>
with_indexed_adjacency<Mesh, T> adapt_indexed(Mesh& mesh) {
    return with_indexed_adjacency<Mesh, T>(mesh);
}

/// The default flavour (indexed).
template <class Mesh, class T = default_traits<Mesh>>
    requires indexed_adapter_source_mesh<std::remove_const_t<Mesh>, T>
with_adjacency<Mesh, T> adapt(Mesh& mesh) {
    return adapt_indexed<Mesh, T>(mesh);
}

}  // namespace hmira
