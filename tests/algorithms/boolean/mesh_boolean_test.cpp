// mesh_boolean: boxes in general position, touching along a face, an edge or a vertex, coplanar
// overlaps, nesting, identical and nearly identical inputs, random rotations. Each result is
// checked by routes independent of the arrangement: the volume identity
// vol(A u B) + vol(A n B) = vol(A) + vol(B), the expected volume, closedness (every directed edge
// has its reverse), validate() and self_intersections().
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>

#include <hmira/algorithms/boolean/mesh_boolean.hpp>
#include <hmira/algorithms/validation/self_intersections.hpp>
#include <hmira/algorithms/validation/validate.hpp>

#include "algorithms/boolean/boolean_support.hpp"
#include "support/checks.hpp"
#include "support/models.hpp"

namespace {

using namespace hmira;
using vec = std::array<double, 3>;
using rotation = std::array<vec, 3>;

constexpr rotation identity{vec{1, 0, 0}, vec{0, 1, 0}, vec{0, 0, 1}};

/// A random rotation (from a random unit quaternion), as a matrix of doubles.
rotation random_rotation(std::mt19937_64& g) {
    std::normal_distribution<double> n;
    double w = n(g), x = n(g), y = n(g), z = n(g);
    const double s = std::sqrt(w * w + x * x + y * y + z * z);
    w /= s, x /= s, y /= s, z /= s;
    return {vec{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
            vec{2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
            vec{2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
}

/// The closed, outward-wound triangulated box [lo, hi], its corners rotated by r.
template <class M>
M box(vec lo, vec hi, const rotation& r = identity) {
    io::polygon_soup s;
    for (int i = 0; i < 8; ++i) {
        const vec p{i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]};
        vec q{};
        for (std::size_t k = 0; k < 3; ++k) q[k] = r[k][0] * p[0] + r[k][1] * p[1] + r[k][2] * p[2];
        s.points.push_back(q);
    }
    // Quads (outward), each cut into two triangles.
    const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads)
        for (const auto& t : {std::array{q[0], q[1], q[2]}, std::array{q[0], q[2], q[3]}}) {
            s.indices.insert(s.indices.end(), t.begin(), t.end());
            s.face_offsets.push_back(s.indices.size());
        }
    M m;
    const bool built = bool(detail::copy::build<M, default_traits<M>>(m, s));
    EXPECT_TRUE(built);
    return m;
}

template <class M>
double volume(const M& m) {
    return hmira_test::signed_volume(m);
}

using hmira_test::closed;

template <class M, class O = M>
O run(const M& a, const M& b, boolean_op op, boolean_report* report = nullptr) {
    O out;
    auto r = mesh_boolean(out, a, b, {.op = op});
    if (r && report) *report = *r;
    EXPECT_TRUE(r) << (r ? "" : r.error().message);
    if (r) {
        EXPECT_EQ(r->faces.size(), default_traits<O>::face_count(out));
    }
    return out;
}

/// Faces whose corners are exactly collinear (validate's own area test is in floating point and
/// flags slivers one ulp wide, which the nearly-identical inputs produce legitimately).
template <class M, class T = default_traits<M>>
std::size_t degenerate_faces(const M& m) {
    std::size_t n = 0;
    for (auto f : T::faces(m)) {
        std::vector<predicates::point3> p;
        for (auto v : T::face_vertices(m, f)) p.push_back(T::position(m, v));
        n += p.size() != 3 || predicates::collinear(p[0], p[1], p[2]);
    }
    return n;
}

/// Closed, valid, free of self-intersections (unless touching is allowed), with the volume given.
template <class M>
void check(const M& m, double want_volume, bool manifold = true) {
    EXPECT_TRUE(closed(m));
    EXPECT_EQ(degenerate_faces(m), 0u);
    if (manifold) {
        EXPECT_TRUE(hmira_test::is_valid(m, {.check_geometry = false}));
        auto si = self_intersections(m);
        ASSERT_TRUE(si);
        EXPECT_TRUE(si->empty()) << si->size() << " intersecting pairs";
    }
    EXPECT_NEAR(volume(m), want_volume, 1e-9 * std::max(1.0, std::fabs(want_volume)));
}

/// All four operations on a and b, their volumes against the identity and against expectations.
template <class M>
void all_ops(const M& a, const M& b, double want_intersection, bool manifold = true) {
    const double va = volume(a), vb = volume(b);
    const M u = run(a, b, boolean_op::union_), i = run(a, b, boolean_op::intersection);
    const M d = run(a, b, boolean_op::difference);
    // The symmetric difference of overlapping solids has four faces at each edge of the
    // intersection curve, which only a face-vertex model holds.
    const auto x = run<M, hmira::face_vertex_mesh>(a, b, boolean_op::xor_);
    {
        SCOPED_TRACE("union");
        check(u, va + vb - want_intersection, manifold);
    }
    {
        SCOPED_TRACE("intersection");
        check(i, want_intersection, manifold);
    }
    {
        SCOPED_TRACE("difference");
        check(d, va - want_intersection, manifold);
    }
    {
        SCOPED_TRACE("xor");
        check(x, va + vb - 2 * want_intersection, false);
    }
    EXPECT_NEAR(volume(u) + volume(i), va + vb, 1e-9 * (va + vb));
    // Order independence.
    const M u2 = run(b, a, boolean_op::union_);
    EXPECT_NEAR(volume(u2), volume(u), 1e-9 * (va + vb));
    EXPECT_EQ(default_traits<M>::face_count(u2), default_traits<M>::face_count(u));
}

template <class M>
class mesh_boolean_test : public ::testing::Test {};
using models = ::testing::Types<hmira::halfedge_mesh, hmira::face_vertex_mesh>;
TYPED_TEST_SUITE(mesh_boolean_test, models);

TYPED_TEST(mesh_boolean_test, boxes_in_general_position) {
    using M = TypeParam;
    const M a = box<M>({0, 0, 0}, {1, 1, 1}), b = box<M>({0.5, 0.25, 0.3}, {1.5, 1.25, 1.3});
    all_ops(a, b, 0.5 * 0.75 * 0.7);
}

TYPED_TEST(mesh_boolean_test, randomly_rotated_boxes) {
    // Rotated, the implicit points round to doubles off their exact places; the result stays
    // closed and its volumes consistent, and any pair of faces that rounding made intersect is
    // counted in the report (checked here by self_intersections).
    using M = TypeParam;
    std::mt19937_64 g(3);
    for (int n = 0; n < 2; ++n) {
        const rotation r = random_rotation(g);
        const M a = box<M>({0, 0, 0}, {1, 1, 1}, r), b = box<M>({0.5, 0.25, 0.3}, {1.5, 1.25, 1.3}, r);
        const double va = volume(a), vb = volume(b);
        for (boolean_op op : {boolean_op::union_, boolean_op::intersection, boolean_op::difference}) {
            boolean_report rep;
            const M m = run(a, b, op, &rep);
            EXPECT_TRUE(closed(m));
            EXPECT_EQ(degenerate_faces(m), rep.degenerate_faces);
            auto si = self_intersections(m);
            ASSERT_TRUE(si);
            EXPECT_EQ(si->size(), rep.rounding_intersections) << n;
            EXPECT_LE(rep.rounding_intersections, 4u);
        }
        const M u = run(a, b, boolean_op::union_), i = run(a, b, boolean_op::intersection);
        // The rotation moves corners by rounding only: volumes stay within 1e-12 of the exact ones.
        EXPECT_NEAR(volume(i), 0.5 * 0.75 * 0.7, 1e-12);
        EXPECT_NEAR(volume(u) + volume(i), va + vb, 1e-9 * (va + vb));
        EXPECT_NEAR(volume(run(a, b, boolean_op::difference)), va - volume(i), 1e-9 * va);
        // A box rotated against an axis-aligned one.
        const M c = box<M>({0, 0, 0}, {1, 1, 1}), d = box<M>({0.2, 0.2, 0.2}, {1.2, 1.2, 1.2}, r);
        const M u2 = run(c, d, boolean_op::union_), i2 = run(c, d, boolean_op::intersection);
        EXPECT_TRUE(closed(u2));
        EXPECT_TRUE(closed(i2));
        EXPECT_NEAR(volume(u2) + volume(i2), 1.0 + volume(d), 1e-9 * (1.0 + volume(d)));
    }
}

TYPED_TEST(mesh_boolean_test, identical_inputs) {
    using M = TypeParam;
    const M a = box<M>({0, 0, 0}, {1, 1, 1});
    check(run(a, a, boolean_op::union_), 1.0);
    check(run(a, a, boolean_op::intersection), 1.0);
    const M d = run(a, a, boolean_op::difference);
    EXPECT_EQ(default_traits<M>::face_count(d), 0u);
}

TYPED_TEST(mesh_boolean_test, boxes_sharing_a_face) {
    using M = TypeParam;
    const M a = box<M>({0, 0, 0}, {1, 1, 1});
    all_ops(a, box<M>({1, 0, 0}, {2, 1, 1}), 0.0);
    all_ops(a, box<M>({1, 0.5, 0.25}, {2, 1.5, 1.25}), 0.0);
}

TYPED_TEST(mesh_boolean_test, boxes_sharing_an_edge_or_a_vertex) {
    using M = TypeParam;
    const M a = box<M>({0, 0, 0}, {1, 1, 1});
    for (const M& b : {box<M>({1, 1, 0}, {2, 2, 1}), box<M>({1, 1, 1}, {2, 2, 2}), box<M>({1, 1, 0.5}, {2, 2, 1.5})}) {
        check(run(a, b, boolean_op::difference), 1.0);
        const M i = run(a, b, boolean_op::intersection);
        EXPECT_EQ(default_traits<M>::face_count(i), 0u);
    }
}

TYPED_TEST(mesh_boolean_test, coplanar_overlapping_faces) {
    using M = TypeParam;
    const M a = box<M>({0, 0, 0}, {1, 1, 1});
    all_ops(a, box<M>({0.5, 0.5, 0}, {1.5, 1.5, 1}), 0.25);
    all_ops(a, box<M>({0, 0, 0}, {1, 1, 0.5}), 0.5);
}

TYPED_TEST(mesh_boolean_test, nested_and_disjoint_shells) {
    using M = TypeParam;
    const M a = box<M>({0, 0, 0}, {1, 1, 1});
    const M inner = box<M>({0.25, 0.25, 0.25}, {0.75, 0.5, 0.5});
    all_ops(a, inner, volume(inner));
    all_ops(a, box<M>({2, 0, 0}, {3, 1, 1}), 0.0);
}

TYPED_TEST(mesh_boolean_test, box_minus_itself_moved_by_one_ulp) {
    using M = TypeParam;
    const double step = std::nextafter(1.0, 2.0) - 1.0;
    const M a = box<M>({0, 0, 0}, {1, 1, 1}), b = box<M>({step, 0, 0}, {1 + 2 * step, 1, 1});
    all_ops(a, b, 1.0 - step);
}

TYPED_TEST(mesh_boolean_test, empty_operands_and_refused_input) {
    using M = TypeParam;
    const M a = box<M>({0, 0, 0}, {1, 1, 1}), empty;
    check(run(a, empty, boolean_op::union_), 1.0);
    check(run(a, empty, boolean_op::difference), 1.0);
    EXPECT_EQ(default_traits<M>::face_count(run(a, empty, boolean_op::intersection)), 0u);
    EXPECT_EQ(default_traits<M>::face_count(run(empty, a, boolean_op::difference)), 0u);
    const M bad = box<M>({0, 0, 0}, {std::numeric_limits<double>::quiet_NaN(), 1, 1});
    M out = box<M>({0, 0, 0}, {1, 1, 1});
    auto r = mesh_boolean(out, a, bad);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, errc::invalid_argument);
    EXPECT_NE(r.error().message.find("vertex 1 of mesh b"), std::string::npos) << r.error().message;
    EXPECT_EQ(default_traits<M>::face_count(out), 12u);
}

TYPED_TEST(mesh_boolean_test, cancellation_leaves_the_output_unchanged) {
    using M = TypeParam;
    const M a = box<M>({0, 0, 0}, {1, 1, 1}), b = box<M>({0.5, 0.5, 0.5}, {2, 2, 2});
    M out = box<M>({0, 0, 0}, {1, 1, 1});
    int calls = 0;
    auto r = mesh_boolean(out, a, b, {.progress = [&](double) { return ++calls < 2; }});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, errc::cancelled);
    EXPECT_EQ(default_traits<M>::face_count(out), 12u);
}

}  // namespace
