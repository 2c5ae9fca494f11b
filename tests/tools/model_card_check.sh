#!/bin/bash
# Issue 25: the model card from the command line.
#  - `model show` prints YAML that `--model` reads back unchanged;
#  - `model show --json` lists every constant with value, unit, source, range;
#  - tripling the Coulomb friction through --model changes `size --json`;
#  - `run --json` reports wall_s and real_time_factor.
# usage: model_card_check.sh SREH_TWIN SCENARIO
set -euo pipefail
bin=$1
scenario=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$bin" model show > "$dir/card.yaml"
"$bin" model show --model "$dir/card.yaml" > "$dir/again.yaml"
cmp "$dir/card.yaml" "$dir/again.yaml" || fail "model show's YAML does not read back as the same card"

"$bin" model show --json > "$dir/card.json"
/usr/bin/python3 - "$dir/card.json" <<'PY' || fail "model show --json"
import json, sys
card = json.load(open(sys.argv[1]))["constants"]
for name in ["torsional_stiffness", "torsional_damping", "coulomb_friction", "stribeck_excess", "cogging_torque",
             "winding_resistance", "winding_inductance", "torque_constant", "current_limit", "loop_delay",
             "winding_to_housing_resistance", "velocity_bandwidth", "current_loop_bandwidth", "control_period"]:
    c = card[name]
    assert set(c) == {"value", "unit", "source", "range"}, (name, c)
    lo, hi = c["range"]
    assert lo <= c["value"] <= hi, (name, c)
    assert c["unit"] and c["source"], name
PY

# Three times the card's 0.008 N m, outside the card's range: the file gives its own.
printf 'constants:\n  coulomb_friction: {value: 0.024, range: [0.005, 0.03]}\n' > "$dir/friction.yaml"
args=(size --angle-deg 90 --load-gcm2 1000 --speed-dps 1000 --json)
"$bin" "${args[@]}" > "$dir/card_size.json"
"$bin" "${args[@]}" --model "$dir/friction.yaml" > "$dir/friction_size.json"
/usr/bin/python3 - "$dir/card_size.json" "$dir/friction_size.json" <<'PY' || fail "tripled friction did not raise the torque"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
assert b["peak_torque_Nm"] > a["peak_torque_Nm"] and b["rms_torque_Nm"] > a["rms_torque_Nm"], (a["peak_torque_Nm"], b["peak_torque_Nm"])
PY

# --emit-scenario replays the sizing with the same model file.
"$bin" size --angle-deg 90 --load-gcm2 1000 --model "$dir/friction.yaml" --emit-scenario "$dir/replay.yaml" > /dev/null
grep -q "^model: \"$dir/friction.yaml\"" "$dir/replay.yaml" || fail "the emitted scenario does not name the --model file"
"$bin" run "$dir/replay.yaml" > /dev/null || fail "the emitted scenario with its model does not pass"

"$bin" run "$scenario" --json > "$dir/run.json"
/usr/bin/python3 - "$dir/run.json" <<'PY' || fail "run --json timing"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["wall_s"] > 0 and r["real_time_factor"] > 0, r
PY
echo "model card: show, read back, JSON, --model changes sizing, emitted scenarios keep it, run timing"
