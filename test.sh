#!/usr/bin/env bash
# Quick start, command 2: install, build, run every test (unit tests and the
# scenario suite) with CTest. CI runs exactly this (.ci/run).
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
