#!/usr/bin/env bash
# Quick start, command 2: install, build, run every test (unit tests, the
# scenario suite, command-line checks) with CTest. CI runs this (.ci/run).
#   ./test.sh              Release build in build/
#   ./test.sh --sanitize   AddressSanitizer + UBSan build in build-asan/ (no rendering)
# Any other arguments go to ctest (e.g. -L scenario, -R Planner).
set -euo pipefail
cd "$(dirname "$0")"
build=build
config=(-DCMAKE_BUILD_TYPE=Release)
if [ "${1:-}" = "--sanitize" ]; then
  shift
  build=build-asan
  config=(-DCMAKE_BUILD_TYPE=Debug -DSREH_SANITIZE=ON -DSREH_WITH_RENDER=OFF -DSREH_BUILD_BENCH=OFF)
fi
./setup.sh
cmake -S . -B "$build" "${config[@]}"
cmake --build "$build" -j"$(nproc)"
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" "$@"
