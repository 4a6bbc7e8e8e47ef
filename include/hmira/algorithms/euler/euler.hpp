// hmira/algorithms/euler/euler.hpp
// All Euler operators (thesis 2.1; Mantyla's MVFS/KVFS, MEV/KEV, MEF/KEF, MFKRH/KFMRH,
// MEKR/KEMR, and MEV/KEV in their general form, split_vertex/join_vertices), each paired with
// its inverse, written once against the raw halfedge layer.
#pragma once

#include "euler_common.hpp"
#include "fill_boundary_loop.hpp"
#include "make_edge_face.hpp"
#include "make_edge_kill_ring.hpp"
#include "make_edge_vertex.hpp"
#include "make_face_kill_ring.hpp"
#include "make_vertex.hpp"
#include "split_vertex.hpp"
