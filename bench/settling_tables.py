#!/usr/bin/python3
"""Regenerates the tables of docs/settling.md from the twin (issue 14, 25).

usage: bench/settling_tables.py SREH_TWIN [--model FILE]

Every cell is `sreh-twin size` of 90 deg moves back and forth (4 moves, the
worst shown; "a..b" where they differ), 3000 deg/s, 100 % acceleration and
jerk, load configured right, 24 V, timeout 1 s; "-" not in the window for
good within the dwell. Where the figure changes by more than 1 ms for
targets up to 4 counts either side (issue 35, `settling_spread` of
`size --json`), the cell is "median (p95)" over those 9 targets instead,
marked "~"; a window some move never held for good gets "-" and, with
"holds X", the smallest window that every move held. Then the convergence
table: the same move once at physics steps of 0.1 / 0.05 / 0.025 ms (`run`
of a generated scenario).
"""
import json
import os
import subprocess
import sys
import tempfile

TWIN = sys.argv[1]
EXTRA = sys.argv[2:]
LOADS = [0, 100, 1000, 5000, 10000, 15000]
TOLERANCES = [0.002, 0.01, 0.05, 0.1, 0.2, 0.5, 1.0]


def size(load, tol, wait_ms, dwell_s):
    cmd = [TWIN, "size", "--angle-deg", "90", "--load-gcm2", str(load), "--tolerance-deg", str(tol),
           "--speed-dps", "3000", "--accel-pct", "100", "--jerk-pct", "100", "--wait-ms", str(wait_ms),
           "--timeout-ms", "1000", "--json"] + (["--dwell-s", str(dwell_s)] if dwell_s else []) + EXTRA
    out = subprocess.run(cmd, capture_output=True, text=True)
    return json.loads(out.stdout)


def span(values):
    if any(v is None for v in values):
        return "-"
    lo, hi = min(values), max(values)
    return f"{1000 * lo:.1f}" if round(1000 * lo, 1) == round(1000 * hi, 1) else f"{1000 * lo:.1f}..{1000 * hi:.1f}"


def cell(result, key):
    """The moves' span, or median (p95) over targets a few counts apart where that spreads by > 1 ms."""
    spread = result["settling_spread"]
    band = spread["settling_s" if key == "settling_s" else "in_window_s"]
    if key == "in_window_s" and spread["never_held"] > 0:
        w = spread["holding_window_deg"]
        return "-" + (f" (holds {w:.4f})" if w is not None else "")
    if spread["chaotic"] and band is not None:
        return f"~{1000 * band['median']:.1f} ({1000 * band['p95']:.1f})"
    return span([m.get(key) for m in result["moves"]])


def table(title, key, wait_ms, dwell_s):
    print(f"\n## {title}\n")
    print("| load g cm^2 | " + " | ".join(f"{t:g} deg" for t in TOLERANCES) + " | overshoot deg | max tracking error deg |")
    print("|---|" + "---|" * (len(TOLERANCES) + 2))
    for load in LOADS:
        cells, overshoot, tracking = [], 0.0, 0.0
        for tol in TOLERANCES:
            result = size(load, tol, wait_ms, dwell_s)
            moves = result["moves"]
            cells.append(cell(result, key))
            overshoot = max([overshoot] + [m.get("overshoot_deg") or 0.0 for m in moves])
            tracking = max([tracking] + [m["max_tracking_error_deg"] for m in moves])
        print(f"| {load} | " + " | ".join(cells) + f" | {overshoot:.4f} | {tracking:.3f} |", flush=True)


SCENARIO = """name: convergence
load: {{inertia_gcm2: {load}}}
sim: {{physics_dt_s: {dt}}}
device:
  isdu:
    - {{index: 65, subindex: 1, value: 30000}}
    - {{index: 65, subindex: 4, value: {load}}}
    - {{index: 65, subindex: 5, value: 15}}
    - {{index: 65, subindex: 6, value: 0}}
    - {{index: 65, subindex: 8, value: 0}}
steps:
  - pd: {{motor_on: 1, parameter_set: 1}}
  - wait_until: {{state: Ready, within_s: 0.02}}
  - pd: {{target_deg: 90, parameter_set: 1, move: 1}}
  - wait_until: {{state: Done, within_s: 1.0}}
  - wait_s: 0.3
"""


def convergence():
    print("\n## Convergence: the physics step changes only numerical error\n")
    print("| load g cm^2 | physics step ms | max tracking error deg | vs 0.025 ms | in window ms | vs 0.025 ms |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as d:
        for load in [0, 5000, 15000]:
            rows = []
            for dt in [0.025e-3, 0.05e-3, 0.1e-3]:
                path = os.path.join(d, "c.yaml")
                with open(path, "w") as f:
                    f.write(SCENARIO.format(load=load, dt=dt))
                out = subprocess.run([TWIN, "run", path, "--json"] + EXTRA, capture_output=True, text=True)
                m = json.loads(out.stdout)["moves"][0]
                rows.append((dt, m["max_tracking_error_deg"], m["in_window_s"]))
            ref = rows[0]
            for dt, te, iw in reversed(rows):
                print(f"| {load} | {dt * 1e3:g} | {te:.4f} | {100 * (te / ref[1] - 1):+.1f} % | {1e3 * iw:.1f} | "
                      f"{1e3 * (iw - ref[2]):+.1f} ms |", flush=True)


convergence()
table("The manual's settling time (`settling_s`), waiting time 0 (the issue's set, dwell 0)", "settling_s", 0, 0)
table("Entered the window for good (`in_window_s`), waiting time 0, dwell 0.2 s", "in_window_s", 0, 0.2)
table("The manual's settling time, waiting time 5 ms", "settling_s", 5, 0)
table("The manual's settling time, default waiting time 25 ms", "settling_s", 25, 0)
