#!/usr/bin/env bash
# Quick start, command 1: install, build, run the demo scenario; writes
# out/demo.mp4 (video), out/demo-report/index.html (report), out/demo.csv (trace).
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSREH_BUILD_TESTS=OFF -DSREH_BUILD_BENCH=OFF
cmake --build build -j"$(nproc)" --target sreh-twin
mkdir -p out
./build/sreh-twin run scenarios/demo.yaml --trace out/demo.csv --video out/demo.mp4 --report out/demo-report
echo "wrote out/demo.mp4, out/demo-report/index.html, out/demo.csv"
