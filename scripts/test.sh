#!/usr/bin/env bash
# The README's test command: installs what is missing; builds the programs, examples and
# benchmarks in Release with -Wall -Wextra -Werror and runs the tests that need an optimised or
# unsanitised build; builds everything again under AddressSanitizer + UBSan (also -Werror) and
# runs every test there; runs the viewer
# tests in headless Chromium and the Python package's tests in a fresh venv, fuzzes each parser
# briefly, and builds a small consumer project against the installed package.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
start=$(date +%s)

bash scripts/install-deps.sh
bash scripts/test-data.sh build/test-data
# The viewer's JavaScript (three.js, pinned by viewer/package-lock.json, bundled by esbuild) is
# committed as viewer/dist/hmira-viewer.js, so every build embeds it without node: check that it
# is what the sources make now.
bash viewer/check-bundle.sh
# The house layout and format: every C++ file formatted by .clang-format (clang-format-16); no
# header over 700 lines, and each algorithm header's entry point within its first 100 lines.
bash scripts/check-format.sh
python3 scripts/check-layout.py

common=(-G Ninja -DHMIRA_WERROR=ON -DHMIRA_BUILD_TESTS=ON -DHMIRA_BUILD_APPS=ON -DHMIRA_BUILD_EXAMPLES=ON
        -DHMIRA_TEST_DATA_DIR="$PWD/build/test-data")

echo "== plain build (Release, -Wall -Wextra -Werror: programs, examples, benchmarks, script tests)"
# The gtest suites are compiled once, in the sanitizer pass below; here only those it cannot
# stand in for (labels full_size and compile_fail, see tests/CMakeLists.txt).
# -O1, not CMake's Release -O3: this pass checks that everything compiles warning-free and runs the
# few full-size tests (61 s in all); -O3 doubled its compile time (apps/hmira/cmd_mc.cpp: 45 s at
# -O3, 33 s at -O2, 23 s at -O1). scripts/bench.sh builds the benchmarks at -O3 to time them.
cmake -S . -B build/test "${common[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
      -DHMIRA_BUILD_BENCHMARKS=ON -DHMIRA_BUILD_ALL_TEST_SUITES=OFF >/dev/null
cmake --build build/test -j"$jobs"
(cd build/test && ctest --output-on-failure -j"$jobs" --timeout 600)
echo "plain pass finished after $(( $(date +%s) - start )) s"

echo "== viewer pages in headless Chromium (Playwright from PyPI drives Debian's chromium)"
bash tests/browser/run.sh build/test
echo "browser tests finished after $(( $(date +%s) - start )) s"

echo "== Python package: pip install . into a fresh venv, type-stub check, pytest"
# The extension at -O1, as the plain pass: -O3 doubles its compile time, and the benchmarks, not
# these tests, time it (bench/python installs the Release build into the benchmark venv).
HMIRA_PY_OPT=-O1 HMIRA_TEST_DATA="$PWD/build/test-data" HMIRA_CLI="$PWD/build/test/apps/hmira/hmira" bash scripts/python.sh
echo "python pass finished after $(( $(date +%s) - start )) s"

echo "== API reference (Doxygen; fails on any undocumented public entity)"
bash scripts/docs.sh build/docs

echo "== sanitizer build (AddressSanitizer + UndefinedBehaviorSanitizer, clang 16)"
# -O0: compiles in half the time of -O1 (measured on bevel_test.cpp: 59 s vs 113 s). Clang 16,
# not GCC 12: the typed suites compile 2-2.6x faster with it at -O0 (decimate_test.cpp 26 s vs
# 66 s); with GCC this pass took ~2000 of CI's 2727 s. The plain pass above builds the programs,
# examples and benchmarks with GCC, so both compilers compile the headers with -Werror.
# -g0: line tables cost a fifth of this pass's compile time (loop_test.cpp: 32.5 s of CPU with -g1,
# 26.5 s with -g0); a report still names every function on its stack, and a local build with -g1
# adds the lines.
cmake -S . -B build/asan "${common[@]}" -DCMAKE_CXX_COMPILER=clang++-16 -DHMIRA_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O0 -g0" -DHMIRA_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build/asan -j"$jobs"
(cd build/asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
   ctest --output-on-failure -j"$jobs" --timeout 900 -LE compile_fail)
echo "sanitizer pass finished after $(( $(date +%s) - start )) s"

echo "== fuzz the mesh, volume and point parsers (libFuzzer, clang 14, 11 targets x 18 s, fixed seed)"
bash fuzz/run.sh 18 build/fuzz

echo "== install and consume with find_package(hmira CONFIG)"
rm -rf build/install build/consumer
cmake --install build/test --prefix build/install >/dev/null
cmake -S cmake/consumer-test -B build/consumer -G Ninja -DCMAKE_PREFIX_PATH="$PWD/build/install" >/dev/null
cmake --build build/consumer >/dev/null
./build/consumer/hmira-consumer
echo "all passes finished after $(( $(date +%s) - start )) s"
