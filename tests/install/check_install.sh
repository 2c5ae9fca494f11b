#!/usr/bin/env bash
# CTest install.consumer (issue 13): `cmake --install` into a fresh prefix, a
# tiny project finds the package and links sreh_twin::device_logic and
# sreh_twin::twin, runs; then the installed tree is moved as a whole and the
# installed sreh-twin still finds its models (relative to where it is).
# usage: check_install.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$source/tests/install/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/consumer-configure.log"
cmake --build "$work/consumer" -j2 > "$work/consumer-build.log"
"$work/consumer/consumer"
mv "$work/prefix" "$work/moved"
# Not the source tree, not the build's install prefix: only the moved tree has the models.
cd "$work"
"$work/moved/bin/sreh-twin" --version | tee "$work/version.txt"
grep -q "models: $work/moved/share/sreh_twin/models" "$work/version.txt"
"$work/moved/bin/sreh-twin" run "$source/scenarios/load_mjcf_gripper.yaml" --json > /dev/null
echo "install: consumer built and ran; moved tree finds its models"
