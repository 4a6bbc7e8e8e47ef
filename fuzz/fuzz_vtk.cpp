// fuzz/fuzz_vtk.cpp
// libFuzzer target for the VTK parser (legacy .vtk and XML .vtp, told apart by their bytes) (see fuzz_io.hpp for the property checked).
#include <cstdio>
#include <cstdlib>

#include "fuzz_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto problem = hmira_fuzz::one_input(hmira::io::file_format::vtp, data, size);
    if (!problem.empty()) {
        std::fprintf(stderr, "property violated: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
