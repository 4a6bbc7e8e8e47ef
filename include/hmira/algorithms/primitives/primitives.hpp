// hmira/algorithms/primitives/primitives.hpp
// The add/remove primitives of thesis 4.2 (vertex, edge, face), each under the weakest concept
// it needs (face_erasable_mesh, vertex_erasable_mesh, halfedge_mutable_mesh, mesh_builder), each
// within the thesis's allowed complexity.
#pragma once

#include "add_remove_edge.hpp"
#include "add_remove_face.hpp"
#include "add_remove_vertex.hpp"
