// make_solid and mesh_boolean on closed inputs that intersect themselves or nest: overlapping
// icosahedra given as one soup, three of them meeting at points no pair makes, a shell inside a
// shell (winding number 2) and a hollow one (an inner shell turned inward). Each result is checked
// by routes independent of the winding numbers: its volume against booleans of the separate,
// clean parts (vol(A u B) = vol(A) + vol(B) - vol(A n B)), closedness from the connectivity, and
// self_intersections() (empty unless the report counts pairs that rounding made intersect).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <hmira/algorithms/boolean/make_solid.hpp>
#include <hmira/algorithms/boolean/mesh_boolean.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/validation/self_intersections.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "algorithms/boolean/boolean_support.hpp"
#include "support/checks.hpp"

namespace {

using namespace hmira;
using M = face_vertex_mesh;
using T = default_traits<M>;

M icosahedron(vec3<double> centre, double scale = 1.0) {
    M m;
    EXPECT_TRUE(generate_icosahedron(m, {.scale = scale, .center = centre}));
    return m;
}

/// The meshes as one mesh (a soup of their faces), those marked in `inward` turned inside out.
M soup(const std::vector<M>& parts, const std::vector<bool>& inward = {}) {
    io::polygon_soup s;
    for (std::size_t n = 0; n < parts.size(); ++n) {
        const std::uint32_t base = std::uint32_t(s.points.size());
        for (auto v : T::vertices(parts[n])) {
            const auto p = T::position(parts[n], v);
            s.points.push_back({p.x, p.y, p.z});
        }
        for (auto f : T::faces(parts[n])) {
            std::vector<std::uint32_t> loop;
            for (auto v : T::face_vertices(parts[n], f))
                loop.push_back(base + std::uint32_t(T::vertex_index(parts[n], v)));
            if (n < inward.size() && inward[n]) std::reverse(loop.begin(), loop.end());
            s.indices.insert(s.indices.end(), loop.begin(), loop.end());
            s.face_offsets.push_back(s.indices.size());
        }
    }
    M m;
    EXPECT_TRUE((detail::copy::build<M, T>(m, s)));
    return m;
}

double volume(const M& m) { return hmira_test::signed_volume(m); }

M boolean(const M& a, const M& b, boolean_op op) {
    M out;
    auto r = mesh_boolean(out, a, b, {.op = op});
    EXPECT_TRUE(r) << r.error().message;
    return out;
}

/// Closed, free of self-intersections but for those the report counts, with the volume given.
void check(const M& m, const boolean_report& report, double want) {
    EXPECT_TRUE(hmira_test::closed(m));
    auto si = self_intersections(m);
    ASSERT_TRUE(si);
    EXPECT_EQ(si->size(), report.rounding_intersections);
    EXPECT_EQ(report.faces.size(), T::face_count(m));
    EXPECT_NEAR(volume(m), want, 1e-9 * std::max(1.0, std::fabs(want)));
}

M solid(const M& in, boolean_report* report = nullptr) {
    M out;
    auto r = make_solid(out, in);
    EXPECT_TRUE(r) << r.error().message;
    if (r && report) *report = *r;
    return out;
}

TEST(make_solid, two_overlapping_icosahedra_as_one_soup_give_their_union) {
    for (const vec3<double> shift : {vec3<double>{0.6, 0.3, 0.2}}) {
        SCOPED_TRACE(testing::Message() << shift.x << " " << shift.y << " " << shift.z);
        const M a = icosahedron({0, 0, 0}), b = icosahedron(shift);
        const double want = volume(a) + volume(b) - volume(boolean(a, b, boolean_op::intersection));
        boolean_report rep;
        const M out = solid(soup({a, b}), &rep);
        check(out, rep, want);
    }
}

TEST(make_solid, seeded_soups_on_a_grid_give_the_union_or_are_refused_for_coplanar_faces) {
    // Shifts on a 0.05 grid put vertices on faces and edges through edges within the soup.
    std::mt19937_64 g(5);
    std::uniform_real_distribution<double> u(-24, 24);
    for (int n = 0; n < 4; ++n) {
        const vec3<double> shift{std::round(u(g)) * 0.05, std::round(u(g)) * 0.05, std::round(u(g)) * 0.05};
        SCOPED_TRACE(testing::Message() << shift.x << " " << shift.y << " " << shift.z);
        const M a = icosahedron({0, 0, 0}), b = icosahedron(shift);
        M out;
        auto r = make_solid(out, soup({a, b}));
        if (!r) {
            EXPECT_EQ(r.error().code, errc::unsupported);
            continue;
        }
        check(out, *r, volume(a) + volume(b) - volume(boolean(a, b, boolean_op::intersection)));
    }
}

TEST(make_solid, three_icosahedra_meeting_at_triple_points) {
    const M a = icosahedron({0, 0, 0}), b = icosahedron({0.7, 0.1, 0.05}), c = icosahedron({0.3, 0.6, -0.2});
    const M ab = boolean(a, b, boolean_op::union_);
    const double want = volume(boolean(ab, c, boolean_op::union_));
    boolean_report rep;
    check(solid(soup({a, b, c}), &rep), rep, want);
}

TEST(make_solid, a_clean_mesh_is_kept_as_it_is) {
    const M a = icosahedron({0.25, 0, 0});
    boolean_report rep;
    const M out = solid(a, &rep);
    check(out, rep, volume(a));
    EXPECT_EQ(T::face_count(out), 20u);
}

TEST(make_solid, a_shell_inside_a_shell_keeps_the_outer_one) {
    const M outer = icosahedron({0, 0, 0}), inner = icosahedron({0.1, 0, 0}, 0.4);
    boolean_report rep;
    const M out = solid(soup({outer, inner}), &rep);
    check(out, rep, volume(outer));
    EXPECT_EQ(T::face_count(out), 20u);
    // Turned inward, the inner shell bounds a hole: both are kept.
    const M hollow = solid(soup({outer, inner}, {false, true}), &rep);
    check(hollow, rep, volume(outer) - volume(inner));
    EXPECT_EQ(T::face_count(hollow), 40u);
}

TEST(make_solid, an_open_mesh_is_refused_and_the_output_left_alone) {
    const M a = icosahedron({0, 0, 0});
    io::polygon_soup s;
    for (auto v : T::vertices(a)) {
        const auto p = T::position(a, v);
        s.points.push_back({p.x, p.y, p.z});
    }
    std::size_t n = 0;
    for (auto f : T::faces(a)) {
        if (n++ == 0) continue;
        for (auto v : T::face_vertices(a, f)) s.indices.push_back(std::uint32_t(T::vertex_index(a, v)));
        s.face_offsets.push_back(s.indices.size());
    }
    M open;
    ASSERT_TRUE((detail::copy::build<M, T>(open, s)));
    M out = icosahedron({0, 0, 0});
    auto r = make_solid(out, open);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, errc::unsupported);
    EXPECT_EQ(T::face_count(out), 20u);
}

TEST(make_solid, coplanar_overlapping_triangles_are_refused) {
    // Boxes whose top and bottom faces overlap in one plane: not supported with winding numbers
    // yet, refused rather than guessed.
    io::polygon_soup s;
    const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& [lo, hi] : {std::pair{vec3<double>{0, 0, 0}, vec3<double>{1, 1, 1}},
                                 std::pair{vec3<double>{0.5, 0.25, 0}, vec3<double>{1.5, 1.25, 1}}}) {
        const std::uint32_t base = std::uint32_t(s.points.size());
        for (int i = 0; i < 8; ++i) s.points.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
        for (const auto& q : quads) {
            for (std::uint32_t c : q) s.indices.push_back(base + c);
            s.face_offsets.push_back(s.indices.size());
        }
    }
    M boxes;
    ASSERT_TRUE((detail::copy::build<M, T>(boxes, s)));
    M out = icosahedron({0, 0, 0});
    auto r = make_solid(out, boxes);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, errc::unsupported);
    EXPECT_EQ(T::face_count(out), 20u);
}

/// Closed and free of self-intersections.
void clean(const M& m) {
    EXPECT_TRUE(hmira_test::closed(m));
    auto si = self_intersections(m);
    ASSERT_TRUE(si);
    EXPECT_TRUE(si->empty());
}

TEST(mesh_boolean_self_intersecting, union_and_intersection_with_a_soup_satisfy_the_volume_identity) {
    // vol(A) of the self-intersecting soup A is that of the clean union of its parts.
    const M a1 = icosahedron({0, 0, 0}), a2 = icosahedron({0.6, 0.3, 0.2}), b = icosahedron({0.2, -0.7, 0.4});
    const M a = soup({a1, a2});
    const double va = volume(boolean(a1, a2, boolean_op::union_)), vb = volume(b);
    const M u = boolean(a, b, boolean_op::union_), i = boolean(a, b, boolean_op::intersection);
    clean(u);
    clean(i);
    EXPECT_GT(volume(i), 0.05 * vb);
    EXPECT_NEAR(volume(u) + volume(i), va + vb, 1e-9 * (va + vb));
}

TEST(mesh_boolean_self_intersecting, difference_with_a_soup_is_that_with_the_clean_union_of_its_parts) {
    const M a1 = icosahedron({0, 0, 0}), a2 = icosahedron({0.6, 0.3, 0.2}), b = icosahedron({0.2, -0.7, 0.4});
    const M d = boolean(soup({a1, a2}), b, boolean_op::difference);
    clean(d);
    EXPECT_NEAR(volume(d), volume(boolean(boolean(a1, a2, boolean_op::union_), b, boolean_op::difference)), 1e-9);
}

TEST(mesh_boolean_self_intersecting, a_doubly_covered_region_counts_once) {
    // a winds twice around its inner shell: the union keeps the outer surface only, and the
    // intersection with a mesh that crosses both shells is that mesh's part inside the outer one.
    const M outer = icosahedron({0, 0, 0}), inner = icosahedron({0.1, 0, 0}, 0.4);
    const M a = soup({outer, inner}), b = icosahedron({0.9, 0.2, 0.1}, 0.8);
    const M u = boolean(a, b, boolean_op::union_), i = boolean(a, b, boolean_op::intersection);
    EXPECT_NEAR(volume(u), volume(boolean(outer, b, boolean_op::union_)), 1e-9);
    EXPECT_NEAR(volume(i), volume(boolean(outer, b, boolean_op::intersection)), 1e-9);
    EXPECT_NEAR(volume(u) + volume(i), volume(outer) + volume(b), 1e-9);
    EXPECT_TRUE(hmira_test::closed(u));
    EXPECT_TRUE(hmira_test::closed(i));
    const M far = icosahedron({5, 0, 0});
    EXPECT_EQ(T::face_count(boolean(a, far, boolean_op::union_)), 40u);
}

}  // namespace
