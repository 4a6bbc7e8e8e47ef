// copy_mesh between every pair of models that makes sense: every model into halfedge_mesh, and
// halfedge_mesh into every model. Each copy is checked through the report's maps against the
// source, read independently through both models' traits: positions, each face's loop (up to
// rotation), the counts and the topology; the copy is validated. A refused copy leaves the
// destination as it was, and a user's plain struct runs decimate by a copy in and a copy back.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <hmira/algorithms/copy/copy_mesh.hpp>
#include <hmira/algorithms/decimation/decimate.hpp>
#include <hmira/algorithms/euler/make_face_kill_ring.hpp>
#include <hmira/algorithms/generators/grid.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/generators/torus.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/algorithms/validation/validate.hpp>

#include "plain_struct_mesh/plain_mesh.hpp"
#include "support/models.hpp"
#include "support/snapshot.hpp"

// A face list that stores whatever it is given (no checks in add_face), to hand copy_mesh the
// bad input a careful model would never hold.
namespace loose {
struct mesh {
    std::vector<std::array<double, 3>> points;
    std::vector<std::vector<int>> faces;
};
}  // namespace loose

template <>
struct hmira::mesh_traits<loose::mesh> {
    using mesh = loose::mesh;
    using vertex_handle = int;
    using face_handle = int;
    using scalar = double;
    static auto vertices(const mesh& m) { return std::views::iota(0, static_cast<int>(m.points.size())); }
    static auto faces(const mesh& m) { return std::views::iota(0, static_cast<int>(m.faces.size())); }
    static std::size_t vertex_count(const mesh& m) { return m.points.size(); }
    static std::size_t face_count(const mesh& m) { return m.faces.size(); }
    static std::size_t vertex_index(const mesh&, int v) { return static_cast<std::size_t>(v); }
    static std::size_t vertex_index_bound(const mesh& m) { return m.points.size(); }
    static std::size_t face_index(const mesh&, int f) { return static_cast<std::size_t>(f); }
    static std::size_t face_index_bound(const mesh& m) { return m.faces.size(); }
    static std::span<const int> face_vertices(const mesh& m, int f) { return m.faces[static_cast<std::size_t>(f)]; }
    static hmira::vec3<double> position(const mesh& m, int v) {
        const auto& p = m.points[static_cast<std::size_t>(v)];
        return {p[0], p[1], p[2]};
    }
};

namespace {

using namespace hmira_test;
using HT = hmira::default_traits<hmira::halfedge_mesh>;

static_assert(hmira::copy_source_mesh<loose::mesh> && !hmira::copy_target_mesh<loose::mesh>);
static_assert(hmira::copy_source_mesh<studio::plain_mesh> && hmira::copy_target_mesh<studio::plain_mesh>);

/// Whether `b` is `a` started at another corner (same winding).
bool same_loop_up_to_rotation(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
    if (a.size() != b.size()) return false;
    if (a.empty()) return true;
    for (std::size_t s = 0; s < b.size(); ++s) {
        bool all = true;
        for (std::size_t k = 0; k < a.size() && all; ++k) all = a[k] == b[(s + k) % b.size()];
        if (all) return true;
    }
    return false;
}

/// Checks a copy through its maps, reading both meshes through their own traits.
template <class MS, class MD, class TS = hmira::default_traits<MS>, class TD = hmira::default_traits<MD>>
void expect_copy(const MS& src, const MD& dst, const hmira::copy_mesh_report<MD, TD>& r) {
    using SD = typename TD::scalar;
    EXPECT_EQ(TD::vertex_count(dst), TS::vertex_count(src));
    EXPECT_EQ(TD::face_count(dst), TS::face_count(src));
    EXPECT_EQ(r.vertices, TS::vertex_count(src));
    EXPECT_EQ(r.faces, TS::face_count(src));
    ASSERT_EQ(r.vertex_map.size(), TS::vertex_index_bound(src));
    ASSERT_EQ(r.face_map.size(), TS::face_index_bound(src));
    // Positions, and the vertex map hits every destination vertex once.
    std::set<std::size_t> hit;
    for (auto v : TS::vertices(src)) {
        const auto w = r.vertex_map[TS::vertex_index(src, v)];
        hit.insert(TD::vertex_index(dst, w));
        const auto ps = TS::position(src, v);
        const auto pd = TD::position(dst, w);
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(double(pd[k]), double(static_cast<SD>(ps[k]))) << "vertex " << TS::vertex_index(src, v);
    }
    EXPECT_EQ(hit.size(), TS::vertex_count(src));
    // Each face's loop is the mapped source loop, up to where it starts.
    std::set<std::size_t> faces_hit;
    for (auto f : TS::faces(src)) {
        const auto g = r.face_map[TS::face_index(src, f)];
        faces_hit.insert(TD::face_index(dst, g));
        std::vector<std::size_t> want, got;
        for (auto v : TS::face_vertices(src, f))
            want.push_back(TD::vertex_index(dst, r.vertex_map[TS::vertex_index(src, v)]));
        for (auto w : TD::face_vertices(dst, g)) got.push_back(TD::vertex_index(dst, w));
        EXPECT_TRUE(same_loop_up_to_rotation(want, got)) << "source face " << TS::face_index(src, f);
    }
    EXPECT_EQ(faces_hit.size(), TS::face_count(src));
    const auto a = hmira::mesh_topology<MS, TS>(src);
    const auto b = hmira::mesh_topology<MD, TD>(dst);
    EXPECT_EQ(b.vertices, a.vertices);
    EXPECT_EQ(b.edges, a.edges);
    EXPECT_EQ(b.faces, a.faces);
    EXPECT_EQ(b.genus, a.genus);
    EXPECT_EQ(b.boundary_loops, a.boundary_loops);
    EXPECT_EQ(b.components, a.components);
    const auto problems = hmira::validate<MD, TD>(dst);
    EXPECT_TRUE(problems.empty()) << problems.front().message;
}

constexpr hmira::copy_mesh_options with_maps{.vertex_map = true, .face_map = true};

/// Sources every model can hold: an icosahedron, a triangle grid (a boundary), and for polygon
/// models a quad torus (genus 1) and a quad grid.
template <class M>
std::vector<M> sources() {
    std::vector<M> out;
    out.emplace_back();
    EXPECT_TRUE(hmira::generate_icosahedron(out.back()));
    out.emplace_back();
    EXPECT_TRUE(hmira::generate_grid(out.back(), {.columns = 3, .rows = 2, .triangles = true}));
    if constexpr (hmira::polygon_mesh_builder<M>) {
        out.emplace_back();
        EXPECT_TRUE(hmira::generate_torus(out.back(), {.rings = 6, .sides = 4}));
        out.emplace_back();
        EXPECT_TRUE(hmira::generate_grid(out.back(), {.columns = 3, .rows = 2}));
    }
    return out;
}

/// A halfedge_mesh with gaps in its indices: a triangulated torus, decimated.
hmira::halfedge_mesh decimated_torus() {
    hmira::halfedge_mesh m;
    EXPECT_TRUE(hmira::generate_torus(m, {.rings = 12, .sides = 8}));
    auto d = hmira::decimate(m, {.target_faces = 100});
    EXPECT_TRUE(d) << d.error().message;
    EXPECT_LT(HT::vertex_count(m), HT::vertex_index_bound(m));
    return m;
}

template <class M>
class copy_mesh_test : public ::testing::Test {};
TYPED_TEST_SUITE(copy_mesh_test, all_models);

TYPED_TEST(copy_mesh_test, every_model_copies_into_halfedge_mesh) {
    using M = TypeParam;
    for (const M& src : sources<M>()) {
        hmira::halfedge_mesh dst;
        ASSERT_TRUE(hmira::generate_cube(dst));  // replaced by the copy
        auto r = hmira::copy_mesh(src, dst, with_maps);
        ASSERT_TRUE(r) << r.error().message;
        expect_copy(src, dst, *r);
    }
}

TYPED_TEST(copy_mesh_test, halfedge_mesh_copies_into_every_model) {
    using M = TypeParam;
    std::vector<hmira::halfedge_mesh> srcs = sources<hmira::halfedge_mesh>();
    srcs.push_back(decimated_torus());
    for (const auto& src : srcs) {
        if (!hmira::polygon_mesh_builder<M>) {
            bool triangles = true;
            for (auto f : HT::faces(src)) triangles &= std::ranges::distance(HT::face_vertices(src, f)) == 3;
            if (!triangles) continue;
        }
        M dst;
        ASSERT_TRUE(hmira::generate_tetrahedron(dst));  // replaced by the copy
        auto r = hmira::copy_mesh(src, dst, with_maps);
        ASSERT_TRUE(r) << r.error().message;
        expect_copy(src, dst, *r);
    }
}

TYPED_TEST(copy_mesh_test, a_copy_the_destination_refuses_leaves_it_unchanged) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    M dst;
    ASSERT_TRUE(hmira::generate_icosahedron(dst));
    const auto before = snapshot<M>(dst);
    // Face 2 repeats a corner: every model refuses it.
    loose::mesh degenerate{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2}, {2, 1, 3}, {0, 3, 0}}};
    auto r = hmira::copy_mesh(degenerate, dst);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().element, 2);
    EXPECT_NE(r.error().message.find("copy_mesh: source face 2 refused by the destination: "), std::string::npos)
        << r.error().message;
    EXPECT_EQ(r.error().message.find('\n'), std::string::npos);
    EXPECT_EQ(snapshot<M>(dst), before);
    if constexpr (hmira::halfedge_navigable_mesh<M, T>) {
        // A third face on edge 0-1: a half-edge model refuses it.
        loose::mesh fin{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}};
        auto n = hmira::copy_mesh(fin, dst);
        ASSERT_FALSE(n);
        EXPECT_EQ(n.error().element, 2);
        EXPECT_NE(n.error().message.find("source face 2"), std::string::npos) << n.error().message;
        EXPECT_EQ(snapshot<M>(dst), before);
    }
    if constexpr (!hmira::polygon_mesh_builder<M, T>) {
        loose::mesh quad{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}};
        auto q = hmira::copy_mesh(quad, dst);
        ASSERT_FALSE(q);
        EXPECT_EQ(q.error().element, 0);
        EXPECT_EQ(snapshot<M>(dst), before);
    }
}

TYPED_TEST(copy_mesh_test, bad_input_is_refused_naming_the_element_and_leaves_the_destination_unchanged) {
    using M = TypeParam;
    M dst;
    ASSERT_TRUE(hmira::generate_icosahedron(dst));
    const auto before = snapshot<M>(dst);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    loose::mesh bad_point{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, nan, 0}}, {{0, 1, 2}}};
    auto p = hmira::copy_mesh(bad_point, dst);
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().code, hmira::errc::invalid_argument);
    EXPECT_EQ(p.error().element, 3);
    EXPECT_EQ(p.error().message.rfind("copy_mesh: source vertex 3 has a non-finite position", 0), 0u)
        << p.error().message;
    EXPECT_EQ(snapshot<M>(dst), before);

    loose::mesh missing{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {2, 1, 7}}};
    auto m = hmira::copy_mesh(missing, dst);
    ASSERT_FALSE(m);
    EXPECT_EQ(m.error().code, hmira::errc::invalid_handle);
    EXPECT_EQ(m.error().element, 1);
    EXPECT_EQ(m.error().message, "copy_mesh: source face 1 names vertex 7, which is not a live vertex of the source");
    EXPECT_EQ(snapshot<M>(dst), before);

    if constexpr (std::same_as<typename hmira::default_traits<M>::scalar, float>) {
        loose::mesh huge{{{0, 0, 0}, {1e300, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
        auto h = hmira::copy_mesh(huge, dst);
        ASSERT_FALSE(h);
        EXPECT_EQ(h.error().element, 1);
        EXPECT_NE(h.error().message.find("overflows the destination's coordinate type"), std::string::npos)
            << h.error().message;
        EXPECT_EQ(snapshot<M>(dst), before);
    }
}

// A vertex loop cannot hold a face's inner ring: such a face is refused, not copied without it.
TEST(copy_mesh, a_face_with_inner_rings_is_refused) {
    hmira::halfedge_mesh src;
    auto cube = hmira::generate_cube(src);
    ASSERT_TRUE(cube);
    const auto host = cube->faces[0], top = cube->faces[5];
    ASSERT_TRUE(hmira::kill_face_make_ring(src, top, host));  // the top's loop becomes a ring of the bottom
    hmira::face_vertex_mesh dst;
    ASSERT_TRUE(hmira::generate_tetrahedron(dst));
    const auto before = snapshot(dst);
    auto r = hmira::copy_mesh(src, dst);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::unsupported);
    EXPECT_EQ(r.error().element, static_cast<long long>(HT::face_index(src, host)));
    const std::string want = "copy_mesh: source face " + std::to_string(HT::face_index(src, host)) + " has inner rings";
    EXPECT_EQ(r.error().message.rfind(want, 0), 0u) << r.error().message;
    EXPECT_EQ(snapshot(dst), before);
}

TEST(copy_mesh, carries_normals_and_colours_between_models_with_named_properties) {
    hmira::halfedge_mesh src = decimated_torus();
    auto normals = src.add_vertex_property<hmira::vec3<float>>("v:normal");
    auto colors = src.add_vertex_property<std::array<std::uint8_t, 4>>("v:color");
    for (auto v : HT::vertices(src)) {
        const auto i = static_cast<float>(HT::vertex_index(src, v));
        normals[v] = {i, -i, 0.5f};
        colors[v] = {static_cast<std::uint8_t>(HT::vertex_index(src, v) % 256), 7, 8, 255};
    }
    hmira::face_vertex_mesh dst;
    auto r = hmira::copy_mesh(src, dst, with_maps);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_TRUE(r->normals);
    EXPECT_TRUE(r->colors);
    auto dn = dst.get_vertex_property<hmira::vec3<float>>("v:normal");
    auto dc = dst.get_vertex_property<std::array<std::uint8_t, 4>>("v:color");
    ASSERT_TRUE(dn && dc);
    for (auto v : HT::vertices(src)) {
        const auto w = r->vertex_map[HT::vertex_index(src, v)];
        EXPECT_EQ((*dn)[w], normals[v]);
        EXPECT_EQ((*dc)[w], colors[v]);
    }
    // Without attributes, nothing is carried.
    hmira::face_vertex_mesh bare;
    auto b = hmira::copy_mesh(src, bare, {.attributes = false});
    ASSERT_TRUE(b);
    EXPECT_FALSE(b->normals);
    EXPECT_FALSE(bare.get_vertex_property<hmira::vec3<float>>("v:normal"));
}

TEST(copy_mesh, a_mesh_copies_onto_itself) {
    hmira::halfedge_mesh m = decimated_torus();
    const hmira::halfedge_mesh before = m;
    auto r = hmira::copy_mesh(m, m, with_maps);
    ASSERT_TRUE(r) << r.error().message;
    expect_copy(before, m, *r);
}

// A user's own struct runs the half-edge algorithms through a copy in and a copy back.
TEST(copy_mesh, a_plain_struct_is_decimated_through_a_halfedge_copy) {
    using PT = hmira::mesh_traits<studio::plain_mesh>;
    studio::plain_mesh mine;
    ASSERT_TRUE(hmira::generate_torus(mine, {.rings = 24, .sides = 12}));  // 288 quads, genus 1
    const studio::plain_mesh original = mine;
    // [decimate_own]
    hmira::halfedge_mesh work;
    auto in = hmira::copy_mesh(mine, work);                    // your struct into a half-edge mesh
    auto done = hmira::decimate(work, {.target_faces = 200});  // any half-edge algorithm
    auto out = hmira::copy_mesh(work, mine);                   // and back into your struct
    // [decimate_own]
    ASSERT_TRUE(in) << in.error().message;
    ASSERT_TRUE(done) << done.error().message;
    ASSERT_TRUE(out) << out.error().message;
    EXPECT_EQ(in->faces, 288u);
    EXPECT_TRUE(done->triangulated);
    EXPECT_EQ(PT::face_count(mine), 200u);
    EXPECT_EQ(PT::face_count(mine), HT::face_count(work));
    EXPECT_EQ(mine.positions.size(), HT::vertex_count(work));
    EXPECT_TRUE(hmira::validate(mine).empty());
    EXPECT_EQ(hmira::mesh_topology(mine).genus, 1);
    EXPECT_EQ(hmira::mesh_topology(mine).boundary_edges, 0u);
    // The copy back, checked through its maps against the decimated mesh.
    studio::plain_mesh again;
    auto maps = hmira::copy_mesh(work, again, with_maps);
    ASSERT_TRUE(maps) << maps.error().message;
    expect_copy(work, again, *maps);
    EXPECT_EQ(again.positions, mine.positions);
    EXPECT_EQ(again.faces, mine.faces);
    // The first copy, the other way, checked the same way.
    hmira::halfedge_mesh plain_copy;
    auto first = hmira::copy_mesh(original, plain_copy, with_maps);
    ASSERT_TRUE(first) << first.error().message;
    expect_copy(original, plain_copy, *first);
}

TEST(copy_mesh, a_map_needs_nothing_but_is_only_filled_when_asked) {
    hmira::halfedge_mesh src;
    ASSERT_TRUE(hmira::generate_cube(src));
    hmira::face_vertex_mesh dst;
    auto r = hmira::copy_mesh(src, dst);
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->vertex_map.empty());
    EXPECT_TRUE(r->face_map.empty());
    EXPECT_EQ(r->vertices, 8u);
    EXPECT_EQ(r->faces, 6u);
}

}  // namespace
