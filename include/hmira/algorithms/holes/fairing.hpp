// hmira/algorithms/holes/fairing.hpp
// The fairings hole filling offers for the vertices its refinement adds, with the names the
// command line and Python take.
#pragma once

#include <array>
#include <string_view>
#include <utility>

namespace hmira {

/// What fill_hole does to the patch's shape after triangulating the loop.
enum class fairing {
    none,        ///< keep the vertices where refinement put them
    membrane,    ///< uniform Laplacian = 0 at each added vertex: a minimal-area-like patch
    thin_plate,  ///< Laplacian of the Laplacian = 0: a patch that continues the surface's slope
};

/// The fairings' names: "none", "membrane", "thin-plate" (see core/enum_names.hpp).
constexpr auto enum_names(fairing) {
    return std::array{std::pair{fairing::none, std::string_view("none")},
                      std::pair{fairing::membrane, std::string_view("membrane")},
                      std::pair{fairing::thin_plate, std::string_view("thin-plate")}};
}

}  // namespace hmira
