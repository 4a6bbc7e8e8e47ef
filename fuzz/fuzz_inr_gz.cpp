// fuzz/fuzz_inr_gz.cpp
// libFuzzer target for the INRIMAGE-4 reader through gzip (the input is compressed first unless it is gzip already),
// which exercises the bounded inflation (see fuzz_volume.hpp for the property checked).
#include <cstdio>
#include <cstdlib>

#include "fuzz_volume.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto problem = hmira_fuzz::one_inr(data, size, true);
    if (!problem.empty()) {
        std::fprintf(stderr, "property violated: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
