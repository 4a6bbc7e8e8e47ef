// hmira/algorithms/conversion/delaunay_triangulation.hpp
// Forwards to hmira/algorithms/delaunay/delaunay_triangulation.hpp, Delaunay's own family folder;
// include that instead. This forwarding header will go in a later release.
#pragma once

#include "../delaunay/delaunay_triangulation.hpp"
