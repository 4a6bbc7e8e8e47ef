// Locality: the traits operations one truncate, bevel or extrude performs, counted
// through an instrumented traits class, are the same on a small and on a large mesh.
// g++ 12 at -O3 reports a false -Wrestrict inside std::string concatenation in
// euler_common.hpp's name() for this instantiation (GCC bug 105329); not a real overlap.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>

#include <hmira/algorithms/generators/torus.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "algorithms/editing/editing_support.hpp"

namespace {

inline std::uint64_t calls = 0;
inline std::uint64_t whole_mesh_ranges = 0;  // vertices(), faces(), edges(), halfedges(): O(mesh) each

/// halfedge_mesh's traits with every navigation and mutation call counted.
struct counting_traits : hmira::mesh_traits<hmira::halfedge_mesh> {
    using base = hmira::mesh_traits<hmira::halfedge_mesh>;
    using mesh = hmira::halfedge_mesh;
    using H = base::halfedge_handle;
    using V = base::vertex_handle;
    using F = base::face_handle;
    using E = base::edge_handle;
    static H next(const mesh& m, H h) {
        ++calls;
        return base::next(m, h);
    }
    static H prev(const mesh& m, H h) {
        ++calls;
        return base::prev(m, h);
    }
    static H opposite(const mesh& m, H h) {
        ++calls;
        return base::opposite(m, h);
    }
    static V target(const mesh& m, H h) {
        ++calls;
        return base::target(m, h);
    }
    static F face(const mesh& m, H h) {
        ++calls;
        return base::face(m, h);
    }
    static E edge(const mesh& m, H h) {
        ++calls;
        return base::edge(m, h);
    }
    static H vertex_halfedge(const mesh& m, V v) {
        ++calls;
        return base::vertex_halfedge(m, v);
    }
    static H face_halfedge(const mesh& m, F f) {
        ++calls;
        return base::face_halfedge(m, f);
    }
    static auto position(const mesh& m, V v) {
        ++calls;
        return base::position(m, v);
    }
    static void set_position(mesh& m, V v, const hmira::vec3<double>& p) {
        ++calls;
        base::set_position(m, v, p);
    }
    static void set_next(mesh& m, H h, H n) {
        ++calls;
        base::set_next(m, h, n);
    }
    static void set_target(mesh& m, H h, V v) {
        ++calls;
        base::set_target(m, h, v);
    }
    static void set_face(mesh& m, H h, F f) {
        ++calls;
        base::set_face(m, h, f);
    }
    static void set_vertex_halfedge(mesh& m, V v, H h) {
        ++calls;
        base::set_vertex_halfedge(m, v, h);
    }
    static void set_face_halfedge(mesh& m, F f, H h) {
        ++calls;
        base::set_face_halfedge(m, f, h);
    }
    static H new_edge(mesh& m, V a, V b) {
        ++calls;
        return base::new_edge(m, a, b);
    }
    static F new_face(mesh& m) {
        ++calls;
        return base::new_face(m);
    }
    static V add_vertex(mesh& m, const hmira::vec3<double>& p) {
        ++calls;
        return base::add_vertex(m, p);
    }
    static void erase_edge(mesh& m, E e) {
        ++calls;
        base::erase_edge(m, e);
    }
    static void erase_face(mesh& m, F f) {
        ++calls;
        base::erase_face(m, f);
    }
    static void erase_vertex(mesh& m, V v) {
        ++calls;
        base::erase_vertex(m, v);
    }
    static auto vertices(const mesh& m) {
        ++whole_mesh_ranges;
        return base::vertices(m);
    }
    static auto faces(const mesh& m) {
        ++whole_mesh_ranges;
        return base::faces(m);
    }
    static auto edges(const mesh& m) {
        ++whole_mesh_ranges;
        return base::edges(m);
    }
    static auto halfedges(const mesh& m) {
        ++whole_mesh_ranges;
        return base::halfedges(m);
    }
};
using CT = counting_traits;
static_assert(hmira::extrudable_mesh<hmira::halfedge_mesh, CT>);

hmira::halfedge_mesh torus(std::size_t rings) {
    hmira::halfedge_mesh m;
    (void)hmira::generate_torus(m, {.major_radius = 3, .minor_radius = 1, .rings = rings, .sides = 8}).value();
    return m;
}

template <class Op>
std::uint64_t count_calls(std::size_t rings, Op op) {
    auto m = torus(rings);
    calls = 0;
    whole_mesh_ranges = 0;
    op(m);
    // A local edit never enumerates the mesh (index bounds, O(1), are allowed).
    EXPECT_EQ(whole_mesh_ranges, 0u) << "a whole-mesh range was read inside a local edit";
    EXPECT_TRUE(hmira_test::is_valid(m));
    return calls;
}

TEST(editing_locality, the_range_counter_sees_a_whole_mesh_scan) {
    // truncate_all enumerates the vertices by design: the counter must notice.
    auto m = torus(8);
    whole_mesh_ranges = 0;
    ASSERT_TRUE((hmira::truncate_all<hmira::halfedge_mesh, CT>(m)));
    EXPECT_GT(whole_mesh_ranges, 0u);
}

TEST(editing_locality, truncate_bevel_and_extrude_cost_does_not_grow_with_mesh_size) {
    auto truncate_first = [](hmira::halfedge_mesh& m) {
        ASSERT_TRUE((hmira::truncate<hmira::halfedge_mesh, CT>(
            m, *hmira::default_traits<hmira::halfedge_mesh>::vertices(m).begin())));
    };
    auto extrude_first = [](hmira::halfedge_mesh& m) {
        ASSERT_TRUE((hmira::extrude<hmira::halfedge_mesh, CT>(
            m, *hmira::default_traits<hmira::halfedge_mesh>::faces(m).begin(), {.distance = 0.1})));
    };
    auto bevel_first = [](hmira::halfedge_mesh& m) {
        ASSERT_TRUE((hmira::bevel<hmira::halfedge_mesh, CT>(
            m, *hmira::default_traits<hmira::halfedge_mesh>::edges(m).begin(), {.width = 0.05})));
    };
    auto region_of_two = [](hmira::halfedge_mesh& m) {
        auto it = hmira::default_traits<hmira::halfedge_mesh>::faces(m).begin();
        const auto f0 = *it;
        const auto f1 = CT::face(m, CT::opposite(m, CT::face_halfedge(m, f0)));
        const CT::face_handle fs[] = {f0, f1};
        ASSERT_TRUE((hmira::extrude<hmira::halfedge_mesh, CT>(m, fs, {.distance = 0.1})));
    };
    for (auto [name, small, large] :
         {std::tuple{"truncate", count_calls(8, truncate_first), count_calls(400, truncate_first)},
          std::tuple{"extrude", count_calls(8, extrude_first), count_calls(400, extrude_first)},
          std::tuple{"extrude region", count_calls(8, region_of_two), count_calls(400, region_of_two)},
          std::tuple{"bevel", count_calls(8, bevel_first), count_calls(400, bevel_first)}}) {
        EXPECT_GT(small, 0u) << name;
        EXPECT_EQ(small, large) << name << ": traits calls differ between 64 and 3200 faces";
    }
}

// The selections' index_set hashes sparse indices and turns into a bitmap when they are dense
// (a whole-mesh selection); both ways, and back to hashing when a far index arrives, it must
// answer exactly as a std::set does.
TEST(editing_index_set, dense_sparse_and_mixed_sets_answer_like_std_set) {
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 60; ++trial) {
        hmira::detail::editing::index_set s;
        std::set<std::size_t> ref;
        const std::size_t range = trial % 3 == 0 ? 1000 : trial % 3 == 1 ? 100000 : 100000000;
        const int n = 200 + static_cast<int>(rng() % 3000);
        for (int i = 0; i < n; ++i) {
            std::size_t x = trial % 5 == 0 ? static_cast<std::size_t>(i) : rng() % range;  // in order, as a whole mesh
            if (i % 97 == 96) x = rng() % (range * 1000);                                  // now and then a far one
            ASSERT_EQ(s.insert(x), ref.insert(x).second) << "trial " << trial << " index " << x;
            ASSERT_EQ(s.size(), ref.size());
        }
        for (int q = 0; q < 2000; ++q) {
            const std::size_t x = rng() % (2 * range);
            ASSERT_EQ(s.contains(x), ref.count(x) > 0) << "trial " << trial << " index " << x;
        }
        for (auto x : ref) ASSERT_TRUE(s.contains(x)) << "trial " << trial << " lost " << x;
    }
}

}  // namespace
