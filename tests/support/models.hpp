// tests/support/models.hpp
// The mesh models the typed suites run over: hmira's own meshes, and the OpenMesh and CGAL
// models when the test binary links hmira_test_models and those libraries are installed.
#pragma once

#include <gtest/gtest.h>

#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#if __has_include(<hmira/meshes/winged_edge_mesh.hpp>)
#include <hmira/meshes/winged_edge_mesh.hpp>
#define HMIRA_TEST_HAS_WINGED_EDGE 1
#endif

#ifdef HMIRA_TEST_WITH_OPENMESH
#include <hmira/interop/openmesh.hpp>
#endif
#ifdef HMIRA_TEST_WITH_CGAL
#include <CGAL/Simple_cartesian.h>
#include <hmira/interop/cgal.hpp>
#endif

namespace hmira_test {

#ifdef HMIRA_TEST_WITH_OPENMESH
using openmesh_poly = OpenMesh::PolyMesh_ArrayKernelT<>;
using openmesh_tri = OpenMesh::TriMesh_ArrayKernelT<>;
#endif
#ifdef HMIRA_TEST_WITH_CGAL
using cgal_surface_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
#endif

/// Every model hmira ships, plus the interop models when a test binary defines them.
using all_models = ::testing::Types<hmira::face_vertex_mesh, hmira::halfedge_mesh
#ifdef HMIRA_TEST_HAS_WINGED_EDGE
                                    ,
                                    hmira::winged_edge_mesh
#endif
#ifdef HMIRA_TEST_WITH_OPENMESH
                                    ,
                                    openmesh_poly, openmesh_tri
#endif
#ifdef HMIRA_TEST_WITH_CGAL
                                    ,
                                    cgal_surface_mesh
#endif
                                    >;

}  // namespace hmira_test
