// mesh_boolean on an icosahedron against moved copies of itself: the moves put vertices of one on
// edges and faces of the other and edges through edges, the configurations where a constructed
// point has more than one definition and only some of them are well defined. Each result is
// checked by routes independent of the arrangement: every output coordinate finite, the surface
// closed, and the volume identity vol(A u B) + vol(A n B) = vol(A) + vol(B) with
// vol(A - B) = vol(A) - vol(A n B).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include <hmira/algorithms/boolean/mesh_boolean.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "algorithms/boolean/boolean_support.hpp"
#include "support/checks.hpp"

namespace {

using namespace hmira;
using M = face_vertex_mesh;
using T = default_traits<M>;

M icosahedron(vec3<double> centre) {
    M m;
    EXPECT_TRUE(generate_icosahedron(m, {.center = centre}));
    return m;
}

bool finite(const M& m) {
    for (auto v : T::vertices(m)) {
        const auto p = T::position(m, v);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    }
    return true;
}

using hmira_test::closed;

/// Union and intersection (and difference, if asked) of the icosahedron and its copy moved by `shift`.
void check_shift(vec3<double> shift, bool difference = true) {
    SCOPED_TRACE(testing::Message() << "shift " << shift.x << " " << shift.y << " " << shift.z);
    const M a = icosahedron({0, 0, 0}), b = icosahedron(shift);
    const double va = hmira_test::signed_volume(a), vb = hmira_test::signed_volume(b);
    double vol[3] = {};
    const boolean_op ops[3] = {boolean_op::union_, boolean_op::intersection, boolean_op::difference};
    for (int k = 0; k < (difference ? 3 : 2); ++k) {
        M out;
        auto r = mesh_boolean(out, a, b, {.op = ops[k]});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(finite(out)) << "operation " << k;
        EXPECT_TRUE(closed(out)) << "operation " << k;
        vol[k] = hmira_test::signed_volume(out);
    }
    EXPECT_NEAR(vol[0] + vol[1], va + vb, 1e-9 * (va + vb));
    if (difference) {
        EXPECT_NEAR(vol[2], va - vol[1], 1e-9 * va);
    }
    EXPECT_GE(vol[1], 0.0);
    EXPECT_LE(vol[1], va * (1 + 1e-9));
}

// An edge of one solid lies, but for the rounding of the shifted coordinates, in a face plane of
// the other: it crosses that plane exactly, nearly parallel to it, and the crossing point must
// round to a finite, accurate point.
TEST(mesh_boolean_icosahedra, edge_nearly_in_a_face_plane) { check_shift({0.3, 0.2, 0.1}); }

TEST(mesh_boolean_icosahedra, general_position) { check_shift({0.31, 0.17, 0.13}); }

TEST(mesh_boolean_icosahedra, random_shifts) {
    // Half the shifts have components that are multiples of 0.05 (often equal or zero), where vertices
    // and edges of one solid meet the other's faces and edges in the degenerate ways, or nearly so
    // after rounding; the other half are plain random. Union and intersection, for the identity.
    std::mt19937_64 g(7);
    std::uniform_int_distribution<int> step(-12, 12);
    std::uniform_real_distribution<double> any(-0.6, 0.6);
    for (int n = 0; n < 24; ++n) {
        vec3<double> s{};
        for (double* c : {&s.x, &s.y, &s.z}) *c = n % 2 == 0 ? 0.05 * step(g) : any(g);
        check_shift(s, false);
    }
}

}  // namespace
