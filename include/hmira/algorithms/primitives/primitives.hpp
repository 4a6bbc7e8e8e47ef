// hmira/algorithms/primitives/primitives.hpp
// The add/remove primitives of thesis 4.2 (vertex, edge, face), generic over any mesh with
// the raw halfedge layer, each within the thesis's allowed complexity.
#pragma once

#include "add_remove_edge.hpp"
#include "add_remove_face.hpp"
#include "add_remove_vertex.hpp"
