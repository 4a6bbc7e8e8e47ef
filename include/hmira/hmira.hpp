// hmira/hmira.hpp
// Convenience header: the traits, the concepts, the reference meshes and the core algorithms.
// Optional parts (TBB, OpenMesh, CGAL interop, file formats beyond OBJ/OFF) are included on their own.
#pragma once

#include "concepts.hpp"
#include "traits.hpp"
#include "meshes/face_vertex_mesh.hpp"
#include "meshes/halfedge_mesh.hpp"
#include "algorithms/generators/grid.hpp"
#include "algorithms/generators/platonic_solids.hpp"
#include "algorithms/generators/torus.hpp"
#include "algorithms/orientation/flip_normals.hpp"
#include "algorithms/topology/connected_components.hpp"
#include "algorithms/topology/mesh_topology.hpp"
#include "algorithms/validation/validate.hpp"
#include "algorithms/validation/self_intersections.hpp"
#include "algorithms/spatial/inside_closed.hpp"
