#!/bin/bash
# Issue 17 hand-over: `size --emit-scenario` writes a scenario that replays
# the sized cycle (or move) in the twin, and `sreh-twin run` passes it.
# Usage: emit_check.sh SREH_TWIN SIZE_ARGS...
set -euo pipefail
bin=$1
shift
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$bin" size "$@" --emit-scenario "$dir/replay.yaml" > /dev/null
"$bin" run "$dir/replay.yaml"
