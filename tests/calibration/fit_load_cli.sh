#!/usr/bin/env bash
# cli.calibrate_fit_load_names_the_load (tests/tools/CMakeLists.txt, issue 36,
# A-CAL-14): `calibrate --fit load` on a log of a module carrying 5250 g cm^2
# stated as 5000 names the carried load against the stated one in words, and
# the model file it writes names the load in a comment, never as a constant.
#   fit_load_cli.sh SREH_TWIN OUT.yaml CALIBRATE-ARGS...
set -euo pipefail
twin=$1 yaml=$2
shift 2
out=$("$twin" "$@" --out "$yaml")
echo "$out"
grep -Eq 'load_inertia +52[0-9.]+ g cm\^2 +\(stated 5000, 95 % \[' <<<"$out" || { echo "no load_inertia line"; exit 1; }
grep -Eq 'note: the module carries 52[0-9.]+ g cm\^2, not the stated 5000\.0 \(\+[0-9.]+ %' <<<"$out" ||
  { echo "no note naming the carried load"; exit 1; }
grep -q '^# The attached load was fitted too' "$yaml" || { echo "the model file does not name the fitted load"; exit 1; }
if grep -q '^  load' "$yaml"; then echo "the load written as a constant of the model file"; exit 1; fi
