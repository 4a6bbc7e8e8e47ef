// mesh_boolean gives the same result, byte for byte, whatever its thread count: two interlinked
// tori, large enough that the parallel stages split their work into several chunks, under union
// and difference at 1, 2 and 3 threads. The volume identity vol(A u B) + vol(A n B) = vol(A) +
// vol(B) checks, independently of the arrangement, that the results compared are right.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include <hmira/algorithms/boolean/mesh_boolean.hpp>
#include <hmira/algorithms/generators/torus.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "algorithms/boolean/boolean_support.hpp"
#include "support/checks.hpp"

namespace {

using namespace hmira;
using M = face_vertex_mesh;
using T = default_traits<M>;

/// A torus around z at the origin, and one around y whose centre circle links the first's, both
/// tubes thick enough to cross each other all along the link; the second is turned a little off
/// the axes.
std::array<M, 2> interlinked_tori() {
    std::array<M, 2> m;
    EXPECT_TRUE(generate_torus(m[0], {.minor_radius = 0.6, .rings = 24, .sides = 12}));
    EXPECT_TRUE(generate_torus(m[1], {.minor_radius = 0.6, .rings = 24, .sides = 12}));
    for (auto v : T::vertices(m[1])) {
        const auto p = T::position(m[1], v);
        m[1].set_position(v, {p.x + 1.0 + 0.01 * p.z, -p.z - 0.01 * p.x + 0.003, p.y + 0.002});
    }
    return m;
}

/// The output as plain arrays: vertex coordinates, face corners and each face's origin.
struct snapshot {
    std::vector<double> xyz;
    std::vector<std::size_t> corners;
    std::vector<std::size_t> origin;
    bool operator==(const snapshot&) const = default;
};

snapshot take(const M& out, const boolean_report& report) {
    snapshot s;
    for (auto v : T::vertices(out)) {
        const auto p = T::position(out, v);
        s.xyz.insert(s.xyz.end(), {p.x, p.y, p.z});
    }
    for (auto f : T::faces(out))
        for (auto v : T::face_vertices(out, f)) s.corners.push_back(T::vertex_index(out, v));
    for (const auto& o : report.faces) s.origin.insert(s.origin.end(), {o.mesh, o.face});
    return s;
}

TEST(MeshBooleanThreads, result_does_not_depend_on_thread_count) {
    const auto [a, b] = interlinked_tori();
    double volume[2] = {};
    const boolean_op ops[2] = {boolean_op::union_, boolean_op::intersection};
    for (int k = 0; k < 2; ++k) {
        std::vector<snapshot> runs;
        for (unsigned threads : {1u, 2u, 3u}) {
            M out;
            auto r = mesh_boolean(out, a, b, {.op = ops[k], .threads = threads});
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_GT(r->cut_triangles, 100u);
            EXPECT_TRUE(hmira_test::closed(out));
            runs.push_back(take(out, *r));
            if (threads == 1) volume[k] = hmira_test::signed_volume(out);
        }
        EXPECT_FALSE(runs[0].corners.empty());
        EXPECT_TRUE(runs[1] == runs[0]) << "operation " << k << " at 2 threads";
        EXPECT_TRUE(runs[2] == runs[0]) << "operation " << k << " at 3 threads";
    }
    const double va = hmira_test::signed_volume(a), vb = hmira_test::signed_volume(b);
    EXPECT_NEAR(volume[0] + volume[1], va + vb, 1e-9 * (va + vb));
}

}  // namespace
