// tests/algorithms/delaunay/fast_math_probe.cpp
// Compiled by the test delaunay_predicates_refuse_fast_math with -ffast-math: it must fail
// with the predicates' #error message. Never part of a test binary.
#include <hmira/predicates/orient2d.hpp>

int main() { return hmira::predicates::orient2d(0, 0, 1, 0, 0, 1) > 0 ? 0 : 1; }
