// fuzz/fuzz_gltf.cpp
// libFuzzer target for the glTF parser (GLB and .gltf JSON) (see fuzz_io.hpp for the property checked).
#include <cstdio>
#include <cstdlib>

#include "fuzz_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto problem = hmira_fuzz::one_input(hmira::io::file_format::glb, data, size);
    if (!problem.empty()) {
        std::fprintf(stderr, "property violated: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
