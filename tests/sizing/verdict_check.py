#!/usr/bin/python3
"""Issue 35: `size --uncertainty` says one thing in text, JSON, report and
exit code; the recommendation is feasible in every sample; the sampled
constants (the loop tuning included) are listed in every output.

usage: verdict_check.py SREH_TWIN CARD.yaml [--expect-robust | --expect-infeasible] SIZE_ARGS...

With --expect-robust the nominal optimum must fail in a sample and a set
feasible in every sample must be found (a case built so: the optimum sits
at a limit that the sampled constants move); with --expect-infeasible
no sample may be feasible (a case built so: a target below the travel time).

Runs the sizing three times (text, --json, --report) and checks:
- the three exit codes are equal, 0 exactly when JSON `feasible` is true,
  and `feasible` equals `feasible_worst_case`;
- the verdict sentence of the JSON is in the text and on the page, and the
  page's badge is "FEASIBLE IN EVERY SAMPLE" exactly when it is feasible
  (never a plain FEASIBLE badge);
- every constant of the card with a range wider than one value is sampled
  and named in all three outputs (the tuning constants are on the card);
- every sample is counted: feasible + every failure group's samples = samples,
  and the failure groups are named in words (no binding-limit tag);
- a searched answer that the nominal optimum fails in a sample is either
  feasible in every sample (exit 0, slower than the nominal optimum) or
  the verdict says no set is (exit 1); the nominal optimum given as an
  explicit set then fails with exit 1 and the same number of feasible samples.
Prints PASS at the end.
"""
import html
import json
import os
import sys
import tempfile

from size_check import fail, run_size

import yaml

TWIN, CARD = sys.argv[1], sys.argv[2]
EXPECT_ROBUST = "--expect-robust" in sys.argv[3:]
EXPECT_INFEASIBLE = "--expect-infeasible" in sys.argv[3:]
ARGS = [a for a in sys.argv[3:] if a not in ("--expect-robust", "--expect-infeasible")]


def run(args):
    return run_size(TWIN, args)


def check(args, card_ranged):
    with tempfile.TemporaryDirectory() as d:
        text = run(args)
        js = run(args + ["--json"])
        rep = run(args + ["--report", os.path.join(d, "r")])
        page = open(os.path.join(d, "r", "index.html")).read()
    j = json.loads(js.stdout)
    codes = {text.returncode, js.returncode, rep.returncode}
    if len(codes) != 1:
        fail(f"exit codes differ between text, JSON and report: {text.returncode}, {js.returncode}, {rep.returncode}")
    code = codes.pop()
    if (code == 0) != j["feasible"] or j["feasible"] != j["feasible_worst_case"]:
        fail(f"exit {code}, feasible {j['feasible']}, feasible_worst_case {j['feasible_worst_case']}")
    verdict = j["verdict"]
    if verdict not in text.stdout:
        fail(f"the verdict is not in the text: {verdict!r}")
    if html.escape(verdict, quote=False) not in page and html.escape(verdict) not in page:
        fail(f"the verdict is not on the page: {verdict!r}")
    badge = "FEASIBLE IN EVERY SAMPLE" if j["feasible"] else "NOT FEASIBLE IN EVERY SAMPLE"
    if f'id="verdict-answer">{badge}<' not in page:
        fail(f"the page's badge is not {badge}")
    if ("yes, in every sample" in text.stdout) != j["feasible"]:
        fail("the text's feasible line disagrees with the JSON")
    u = j["uncertainty"]
    missing = [n for n in card_ranged if n not in u["sampled"]]
    if missing:
        fail(f"constants with a range on the card not sampled: {missing}")
    for name in u["sampled"]:
        if name not in text.stdout or name not in page:
            fail(f"sampled constant {name} not listed in the text or on the page")
    counted = u["feasible_samples"] + sum(len(g["samples"]) for g in u["failures"])
    if counted != u["samples"]:
        fail(f"{u['feasible_samples']} feasible + failures {counted - u['feasible_samples']} != {u['samples']} samples")
    if u["feasible_samples"] + u["infeasible_samples"] != u["samples"]:
        fail("feasible + infeasible samples != samples")
    for g in u["failures"]:
        if "_" in g["words"] or g["words"] == g["limit"] or g["words"] not in verdict:
            fail(f"failure group not in words in the verdict: {g}")
        if g["words"] not in text.stdout or html.escape(g["words"], quote=False) not in page:
            fail(f"failure group {g['words']!r} missing from the text or the page")
    for key in ("positioning_s", "peak_torque_Nm"):
        b = u["bands"][key]
        if b is not None and not (b["lo"] <= b["p5"] <= b["median"] <= b["p95"] <= b["hi"]):
            fail(f"band {key} out of order: {b}")
    if u["bands"]["positioning_s"] is not None and "median" not in text.stdout:
        fail("no band in the text")
    if "cycle_s_range" in j and j["cycle_s_range"] is not None and j["completed"]:
        lo, hi = j["cycle_s_range"]
        if not lo <= j["cycle_s"] <= hi:
            fail(f"the cycle time {j['cycle_s']} is outside its band {lo} .. {hi}")
    return j, code


def main():
    card = yaml.safe_load(open(CARD))["constants"]
    ranged = [n for n, c in card.items() if c["range"][1] > c["range"][0]]
    j, code = check(ARGS, ranged)
    robust = j["uncertainty"]["robust"]
    if EXPECT_ROBUST and not (robust["searched"] and robust["found"]):
        fail(f"expected a nominal optimum failing in a sample and a set feasible in every one: {j['verdict']}")
    if EXPECT_INFEASIBLE and (code != 1 or j["uncertainty"]["feasible_samples"] != 0):
        fail(f"expected infeasible in every sample: {j['verdict']}")
    if not robust["searched"]:
        if j["mode"] == "recommend" and j["feasible_nominal"] and code != 0:
            fail("a searched answer that held in every sample must exit 0")
    else:
        nominal = robust["nominal_optimum"]
        if nominal["feasible_samples"] >= j["uncertainty"]["samples"]:
            fail("a robust search ran although the nominal optimum held in every sample")
        if robust["found"]:
            if code != 0 or j["uncertainty"]["feasible_samples"] != j["uncertainty"]["samples"]:
                fail("the robust recommendation is not feasible in every sample")
            if j["positioning_s"] < nominal["positioning_s"] or robust["slower_pct"] < 0:
                fail("the robust recommendation is faster than the nominal optimum")
            if f"{robust['slower_pct']:.1f} % slower" not in j["verdict"]:
                fail("the verdict does not say how much slower the recommendation is")
        elif code != 1:
            fail("no robust set, yet exit 0")
        # The nominal optimum, given: infeasible in the same samples.
        given = ARGS + ["--speed-dps", str(nominal["speed_dps"]), "--accel-pct", str(nominal["accel_pct"]),
                        "--jerk-pct", str(nominal["jerk_pct"])]
        g, gcode = check(given, ranged)
        if gcode != 1 or g["uncertainty"]["feasible_samples"] != nominal["feasible_samples"]:
            fail(f"the nominal optimum given: exit {gcode}, {g['uncertainty']['feasible_samples']} feasible samples, "
                 f"expected exit 1 and {nominal['feasible_samples']}")
    print("PASS", j["verdict"])


main()
