// hmira/algorithms/editing/editing.hpp
// The editing functions of 3D editors (thesis 2.2): truncate, bevel and extrude, generic over
// every Euler-capable mesh model and built from the Euler operators.
#pragma once

#include "bevel.hpp"
#include "extrude.hpp"
#include "truncate.hpp"
