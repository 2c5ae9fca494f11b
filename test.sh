#!/usr/bin/env bash
# Quick start, command 2: install, build, run every test (unit tests, the
# scenario suite, command-line checks) with CTest. CI runs this (.ci/run).
#   ./test.sh              Release build in build/
#   ./test.sh --sanitize   AddressSanitizer + UBSan build in build-asan/ (no rendering)
# Any other arguments go to ctest (e.g. -L scenario, -R Planner).
# Tests are always configured on, whatever an earlier ./demo.sh left in the
# CMake cache, and ctest refuses a run with no tests (issue 12).
set -euo pipefail
cd "$(dirname "$0")"
build=build
config=(-DCMAKE_BUILD_TYPE=Release -DSREH_BUILD_TESTS=ON -DSREH_BUILD_BENCH=ON -DSREH_WITH_RENDER=ON)
if [ "${1:-}" = "--sanitize" ]; then
  shift
  build=build-asan
  config=(-DCMAKE_BUILD_TYPE=Debug -DSREH_BUILD_TESTS=ON -DSREH_SANITIZE=ON -DSREH_WITH_RENDER=OFF -DSREH_BUILD_BENCH=OFF)
fi
./setup.sh
cmake -S . -B "$build" "${config[@]}"
cmake --build "$build" -j"$(nproc)"
ctest --test-dir "$build" --no-tests=error --output-on-failure -j"$(nproc)" "$@"
