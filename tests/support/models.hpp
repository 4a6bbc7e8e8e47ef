// tests/support/models.hpp
// The mesh models the typed suites run over. A suite picks the models that satisfy its
// algorithm's concept with hmira_test::models_satisfying.
#pragma once

#include <gtest/gtest.h>

#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#if __has_include(<hmira/meshes/winged_edge_mesh.hpp>)
#include <hmira/meshes/winged_edge_mesh.hpp>
#define HMIRA_TEST_HAS_WINGED_EDGE 1
#endif

namespace hmira_test {

/// Every model hmira ships, plus interop models when a test binary defines them.
using all_models = ::testing::Types<hmira::face_vertex_mesh, hmira::halfedge_mesh
#ifdef HMIRA_TEST_HAS_WINGED_EDGE
                                    , hmira::winged_edge_mesh
#endif
                                    >;

}  // namespace hmira_test
