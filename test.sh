#!/usr/bin/env bash
# Quick start, command 2: install, build, run every test (unit tests, the
# scenario suite, command-line checks) with CTest. CI runs this (.ci/run).
#   ./test.sh              Release build in build/
#   ./test.sh --sanitize   AddressSanitizer + UBSan build in build-asan/ (clang, no rendering; with the fuzz targets)
# Any other arguments go to ctest (e.g. -L scenario, -R Planner).
# Both are unity builds (SREH_UNITY: on unless a ccache launcher is configured;
# docs/performance-ci.md).
# SREH_BUILD_ONLY=1 stops after the build (CI builds the sanitizer tree while
# the Release tests run).
# Tests are always configured on, whatever an earlier ./demo.sh left in the
# CMake cache, and ctest refuses a run with no tests (issue 12).
set -euo pipefail
cd "$(dirname "$0")"
build=build
config=(-DCMAKE_BUILD_TYPE=Release -DSREH_BUILD_TESTS=ON -DSREH_BUILD_BENCH=ON -DSREH_WITH_RENDER=ON)
if [ "${1:-}" = "--sanitize" ]; then
  shift
  build=build-asan
  # clang: it compiles this build ~40 % faster than GCC, and the same build
  # carries the libFuzzer targets (SREH_FUZZ), so CI's fuzz stage builds
  # nothing of its own (SREH_FUZZ_BUILD=build-asan tests/fuzz/run.sh).
  export CC=clang CXX=clang++
  config=(-DCMAKE_BUILD_TYPE=Debug -DSREH_BUILD_TESTS=ON -DSREH_SANITIZE=ON -DSREH_FUZZ=ON -DSREH_WITH_RENDER=OFF -DSREH_BUILD_BENCH=OFF)
  # A build-asan/ that an older test.sh configured with GCC cannot switch compilers.
  if [ -f "$build/CMakeCache.txt" ] && ! grep -q "^CMAKE_CXX_COMPILER:.*clang" "$build/CMakeCache.txt"; then
    rm -rf "$build"
  fi
fi
./setup.sh
cmake -S . -B "$build" "${config[@]}"
cmake --build "$build" -j"$(nproc)"
[ "${SREH_BUILD_ONLY:-0}" = 1 ] && exit 0
# ctest lists skipped tests without their reason unless -V: its JUnit file
# has each test's output, from which tests/skip_reasons.py prints why
# (issue 39).
junit="$PWD/$build/ctest-junit.xml"
rm -f "$junit"
status=0
ctest --test-dir "$build" --no-tests=error --output-on-failure -j"$(nproc)" --output-junit "$junit" "$@" || status=$?
if [ -f "$junit" ]; then /usr/bin/python3 tests/skip_reasons.py "$junit" || true; fi
exit "$status"
