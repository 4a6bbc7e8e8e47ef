// fuzz/fuzz_binvox.cpp
// libFuzzer target for the binvox reader (see fuzz_volume.hpp for the property checked).
#include <cstdio>
#include <cstdlib>

#include "fuzz_volume.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto problem = hmira_fuzz::one_binvox(data, size);
    if (!problem.empty()) {
        std::fprintf(stderr, "property violated: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
