#!/bin/sh
# The gentlest search's answers of two builds, case by case (issue 37,
# A-SIZE-26): `size --json` of every case of a gentle_proxy.py case file
# (key=value words) with BEFORE and AFTER, compared with cmp; where they
# differ only in `simulations` (the runs taken) the answer is the same, else
# the recommended sets and RMS torques are printed.
# usage: gentle_answers.sh BEFORE_SREH_TWIN AFTER_SREH_TWIN CASES.txt OUT_DIR
set -eu
before=$1 after=$2 cases=$3 out=$4
mkdir -p "$out"
n=0 same=0 runs_only=0 differ=0 runs_before=0 runs_after=0
while IFS= read -r line; do
  case "$line" in '#'*|'') continue ;; esac
  n=$((n + 1))
  args=$(echo "$line" | sed -e 's/angle=/--angle-deg /; s/loadfile=/--load /; s/load=/--load-gcm2 /' \
    -e 's/pos=/--max-positioning-ms /; s/cycle=/--max-cycle-ms /; s/dwell=/--dwell-s /' \
    -e 's/V=/--voltage-V /; s/tilt=/--mounting-tilt-deg /')
  # Outputs already there (a run cut short) are kept; a refused load gives none.
  for side in b a; do
    if [ ! -s "$out/${side}_$n.json" ]; then
      exe=$before
      [ "$side" = a ] && exe=$after
      # shellcheck disable=SC2086
      "$exe" size $args --json > "$out/${side}_$n.json" 2> "$out/${side}_$n.err" || true
    fi
  done
  rb=$(grep -o '"simulations": [0-9]*' "$out/b_$n.json" | grep -o '[0-9]*$' || true)
  ra=$(grep -o '"simulations": [0-9]*' "$out/a_$n.json" | grep -o '[0-9]*$' || true)
  runs_before=$((runs_before + ${rb:-0})) runs_after=$((runs_after + ${ra:-0}))
  if cmp -s "$out/b_$n.json" "$out/a_$n.json"; then
    same=$((same + 1))
  elif [ "$(sed 's/"simulations": [0-9]*//' "$out/b_$n.json" | md5sum)" = "$(sed 's/"simulations": [0-9]*//' "$out/a_$n.json" | md5sum)" ]; then
    runs_only=$((runs_only + 1))
  else
    differ=$((differ + 1))
    echo "case $n ($line): answers differ"
    /usr/bin/python3 - "$out/b_$n.json" "$out/a_$n.json" <<'EOF'
import json, sys
for label, path in zip(("before", "after"), sys.argv[1:]):
    j = json.load(open(path))
    s = j.get("recommended", {})
    print("  %-6s feasible %s rms %.6g N m, positioning %.4f s, runs %s, set %s" % (
        label, j["feasible"], j["rms_torque_Nm"], j["positioning_s"], j["simulations"],
        {k: s.get(k) for k in ("speed_dps", "accel_pct", "jerk_pct")}))
EOF
  fi
done < "$cases"
echo "$n cases: $same byte-identical, $runs_only identical but for the runs taken, $differ answered differently; runs $runs_before before, $runs_after after"
