// hmira/algorithms/triangle/triangle.hpp
// All local triangle operators at once: flip_edge, split_edge, split_face, collapse_edge and
// their precondition checks.
#pragma once

#include "collapse_edge.hpp"
#include "flip_edge.hpp"
#include "split_edge.hpp"
#include "split_face.hpp"
