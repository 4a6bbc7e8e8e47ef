// fuzz/fuzz_inr.cpp
// libFuzzer target for the INRIMAGE-4 reader, plain (see fuzz_volume.hpp for the property checked).
#include <cstdio>
#include <cstdlib>

#include "fuzz_volume.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto problem = hmira_fuzz::one_inr(data, size, false);
    if (!problem.empty()) {
        std::fprintf(stderr, "property violated: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
