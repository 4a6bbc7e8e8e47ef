// tests/algorithms/triangle/triangle_support.hpp
// What the triangle-operator suites share: triangulated test shapes, the native validity
// checkers of the interop models, and the skip for models the operators do not accept.
#pragma once

#include <gtest/gtest.h>

#include <sstream>

#include <hmira/algorithms/triangle/triangle.hpp>

#include "algorithms/euler/euler_support.hpp"
#include "support/models.hpp"

#ifdef HMIRA_TEST_WITH_OPENMESH
#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>
#endif
#ifdef HMIRA_TEST_WITH_CGAL
#include <CGAL/boost/graph/helpers.h>
#endif

namespace hmira_test {

/// Skips the current typed test on a model without the triangle operators.
#define HMIRA_REQUIRE_TRIANGLE_OPS(M)                                                              \
    if constexpr (!hmira::triangle_operable_mesh<M> || !::hmira_test::indexed_halfedge_model<M>) { \
        GTEST_SKIP() << "not a triangle_operable_mesh";                                            \
        return;                                                                                    \
    }

/// Each quad of the face list cut along its first diagonal.
inline face_list triangulated(const face_list& g) {
    face_list t{g.points, {}};
    for (const auto& f : g.faces)
        for (std::size_t i = 1; i + 1 < f.size(); ++i) t.faces.push_back({f[0], f[i], f[i + 1]});
    return t;
}

/// The model's own validity check (CGAL is_valid_polygon_mesh, OpenMesh MeshCheckerT), or
/// success on hmira's models, which validate() covers.
template <class M>
::testing::AssertionResult natively_valid(const M& m) {
#ifdef HMIRA_TEST_WITH_CGAL
    if constexpr (std::is_same_v<M, cgal_surface_mesh>) {
        if (CGAL::is_valid_polygon_mesh(m)) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "CGAL::is_valid_polygon_mesh failed";
    }
#endif
#ifdef HMIRA_TEST_WITH_OPENMESH
    if constexpr (std::is_same_v<M, openmesh_poly> || std::is_same_v<M, openmesh_tri>) {
        std::ostringstream os;
        OpenMesh::Utils::MeshCheckerT<M> checker(m);
        if (checker.check(OpenMesh::Utils::MeshCheckerT<M>::CHECK_ALL, os)) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "OpenMesh MeshCheckerT: " << os.str();
    }
#endif
    (void)m;
    return ::testing::AssertionSuccess();
}

/// validate() without the zero-area check (splits at midpoints make collinear corners).
template <class M, class T = hmira::default_traits<M>>
::testing::AssertionResult valid_topology(const M& m) {
    auto r = is_valid<M, T>(m, hmira::validate_options{.relaxed = false, .check_geometry = false, .max_problems = 20});
    if (!r) return r;
    return natively_valid(m);
}

/// The number of vertices joined to v by an edge, counted here.
template <class M, class T = hmira::default_traits<M>>
std::size_t valence(const M& m, typename T::vertex_handle v) {
    return std::size_t(std::ranges::distance(T::adjacent_vertices(m, v)));
}

/// V - E + F, counted here.
template <class M, class T = hmira::default_traits<M>>
long long chi(const M& m) {
    return (long long)T::vertex_count(m) - (long long)T::edge_count(m) + (long long)T::face_count(m);
}

}  // namespace hmira_test
