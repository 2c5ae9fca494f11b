#!/bin/bash
# Calibration time for a 60 s log (issue 26): the identification plan
# (15000 g cm^2) repeated seven times is run on the "module" with hidden
# constants (examples/calibration/hidden_module.yaml), and its 61.6 s master
# log (30789 rows) is calibrated with the five default constants, with
# /usr/bin/time, on one or two sreh-twin binaries. CPU time (user + sys) is
# the cost on a shared machine; wall time counts only on an idle one (the
# load average is printed). docs/calibration.md "Measured".
#   bench/calibration_60s.sh BUILD/sreh-twin [OTHER/sreh-twin]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
first=$1
"$first" calibrate --plan "$out/plan.yaml" --load-gcm2 15000 > /dev/null
# The moves (after the first hold) seven times, then the plan's ending.
awk -v out="$out" '
  /^steps:/ { in_steps = 1; print > (out "/plan60.yaml"); next }
  in_steps && /motor_on: 0/ { tail = 1 }
  !in_steps || tail { if (tail) ending = ending $0 "\n"; else print > (out "/plan60.yaml"); next }
  { if (started) moves = moves $0 "\n"; else { print > (out "/plan60.yaml"); if ($0 ~ /wait_s: 0.1$/) started = 1 } }
  END { for (i = 0; i < 7; ++i) printf "%s", moves > (out "/plan60.yaml");
        sub(/moves: 18\n  moves_completed: 18/, "moves: 126\n  moves_completed: 126", ending);
        printf "%s", ending > (out "/plan60.yaml") }
' "$out/plan.yaml"
"$first" run "$out/plan60.yaml" --model "$here/examples/calibration/hidden_module.yaml" \
  --master-log "$out/log60.csv" > /dev/null 2>&1
echo "log: $(($(wc -l < "$out/log60.csv") - 1)) rows, last t_s $(tail -1 "$out/log60.csv" | cut -d, -f1)"
n=0
for bin in "$@"; do
  n=$((n + 1))
  echo "== $bin (load average: $(cut -d' ' -f1-3 /proc/loadavg))"
  /usr/bin/time -f "calibrate 60 s log: %e s wall, %U s user, %S s sys, %M kB" \
    "$bin" calibrate "$out/log60.csv" --setup "$out/plan.yaml" --load-gcm2 15000 --out "$out/fit_$n.yaml" \
    --json --quiet > "$out/fit_$n.json" || true
  grep -o '"rms_residual_deg": [0-9.e-]*\|"iterations": [0-9]*\|"converged": [a-z]*' "$out/fit_$n.json" | tr '\n' ' '
  echo
done
